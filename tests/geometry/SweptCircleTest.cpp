// SweptCircleTest.cpp - moving circles against circles and boxes (SweptCircle.h): the edge
// rules one test each, symmetry, translation, and the fast-mover guarantee.
#include "hitbox/geometry/SweptCircle.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Sweep.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using hitbox::Circle;
using hitbox::Hit;
using hitbox::sweepCircleVsBox;
using hitbox::sweepCircleVsCircle;
using hitbox::sweepCircleVsMovingCircle;

namespace
{
const Circle ball{{100.f, 100.f}, 20.f};         // the target in most tests
const hitbox::Box wall(100.f, 0.f, 50.f, 100.f); // x 100..150, y 0..100
const float notANumber = std::numeric_limits<float>::quiet_NaN();
const float infinity = std::numeric_limits<float>::infinity();
const float diagonal = std::sqrt(0.5f);

// A point (a circle of radius 0) moving from `start` to `end`: the ray cast of a circle.
Hit segmentVsCircle(hitbox::Vec2 start, hitbox::Vec2 end, const Circle& circle)
{
    return sweepCircleVsCircle(Circle{start, 0.f}, end - start, circle);
}

void expectNear(hitbox::Vec2 actual, hitbox::Vec2 expected, float tolerance = 1e-4f)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance) << ::testing::PrintToString(actual);
    EXPECT_NEAR(actual.y, expected.y, tolerance) << ::testing::PrintToString(actual);
}
} // namespace

// ---- a point moving against a circle ----------------------------------------------------

TEST(SegmentVsCircle, HitsTheNearRimFromEachSide)
{
    const Hit fromLeft = segmentVsCircle({0.f, 100.f}, {200.f, 100.f}, ball);
    ASSERT_TRUE(fromLeft);
    EXPECT_FLOAT_EQ(fromLeft.time, 0.4f);
    EXPECT_EQ(fromLeft.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(fromLeft.point, hitbox::Vec2(80.f, 100.f));
    EXPECT_FALSE(fromLeft.startedInside);

    const Hit fromRight = segmentVsCircle({200.f, 100.f}, {0.f, 100.f}, ball);
    ASSERT_TRUE(fromRight);
    EXPECT_FLOAT_EQ(fromRight.time, 0.4f);
    EXPECT_EQ(fromRight.normal, hitbox::Vec2(1.f, 0.f));

    const Hit fromAbove = segmentVsCircle({100.f, 0.f}, {100.f, 200.f}, ball);
    ASSERT_TRUE(fromAbove);
    EXPECT_EQ(fromAbove.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_EQ(fromAbove.point, hitbox::Vec2(100.f, 80.f));

    const Hit fromBelow = segmentVsCircle({100.f, 200.f}, {100.f, 0.f}, ball);
    ASSERT_TRUE(fromBelow);
    EXPECT_EQ(fromBelow.normal, hitbox::Vec2(0.f, 1.f));
}

TEST(SegmentVsCircle, PassingBesideMisses)
{
    EXPECT_FALSE(segmentVsCircle({0.f, 50.f}, {200.f, 50.f}, ball));
}

TEST(SegmentVsCircle, GrazingTheRimMisses)
{
    // The line y = 80 touches the rim at (100, 80) without ever getting inside.
    EXPECT_FALSE(segmentVsCircle({0.f, 80.f}, {200.f, 80.f}, ball));
}

TEST(SegmentVsCircle, StoppingShortOrEndingExactlyOnTheRimMisses)
{
    EXPECT_FALSE(segmentVsCircle({0.f, 100.f}, {79.f, 100.f}, ball));
    EXPECT_FALSE(segmentVsCircle({0.f, 100.f}, {80.f, 100.f}, ball));
}

TEST(SegmentVsCircle, StartingInsideReportsThePushOut)
{
    const Hit hit = segmentVsCircle({110.f, 100.f}, {300.f, 100.f}, ball);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(hit.depth, 10.f);
    EXPECT_EQ(hit.point, hitbox::Vec2(120.f, 100.f));
}

TEST(SegmentVsCircle, StartingAtTheCentrePushesTowardsMinusX)
{
    const Hit hit = segmentVsCircle({100.f, 100.f}, {100.f, 300.f}, ball);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit.startedInside);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(hit.depth, 20.f);
}

TEST(SegmentVsCircle, StartingOnTheRimGoingInHitsAtTimeZero)
{
    const Hit hit = segmentVsCircle({80.f, 100.f}, {150.f, 100.f}, ball);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
}

TEST(SegmentVsCircle, StartingOnTheRimGoingAwayOrAlongMisses)
{
    EXPECT_FALSE(segmentVsCircle({80.f, 100.f}, {0.f, 100.f}, ball));
    EXPECT_FALSE(segmentVsCircle({80.f, 100.f}, {80.f, 0.f}, ball)); // along the tangent
}

TEST(SegmentVsCircle, ZeroLengthIsAPointTest)
{
    const Hit inside = segmentVsCircle({105.f, 100.f}, {105.f, 100.f}, ball);
    ASSERT_TRUE(inside);
    EXPECT_TRUE(inside.startedInside);
    EXPECT_FALSE(segmentVsCircle({0.f, 0.f}, {0.f, 0.f}, ball));
    EXPECT_FALSE(segmentVsCircle({80.f, 100.f}, {80.f, 100.f}, ball)); // on the rim
}

TEST(SegmentVsCircle, ZeroRadiusCircleIsNeverHit)
{
    // A segment and a point have no area to share, even straight through it.
    EXPECT_FALSE(segmentVsCircle({0.f, 100.f}, {200.f, 100.f}, Circle{{100.f, 100.f}, 0.f}));
    // Nearly through it, where rounding in the quadratic once reported a hit.
    EXPECT_FALSE(segmentVsCircle({-3.40649414f, 32.1486053f}, {-1.23783875f, 77.7040863f},
                                 Circle{{-2.0381062f, 60.8934097f}, 0.f}));
}

TEST(SegmentVsCircle, NegativeRadiusNaNOrInfinityNeverHits)
{
    EXPECT_FALSE(segmentVsCircle({0.f, 100.f}, {200.f, 100.f}, Circle{{100.f, 100.f}, -5.f}));
    EXPECT_FALSE(segmentVsCircle({notANumber, 100.f}, {200.f, 100.f}, ball));
    EXPECT_FALSE(segmentVsCircle({0.f, 100.f}, {infinity, 100.f}, ball));
    EXPECT_FALSE(segmentVsCircle({0.f, 100.f}, {200.f, 100.f}, Circle{{100.f, 100.f}, notANumber}));
}

// ---- circle vs circle --------------------------------------------------------------------

TEST(SweepCircleVsCircle, StopsWithTheRimsTouching)
{
    const Circle mover{{0.f, 100.f}, 10.f};
    const Hit hit = sweepCircleVsCircle(mover, {200.f, 0.f}, ball);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.35f); // centre at x = 70: 30 px apart, the radii added
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(hit.point, hitbox::Vec2(80.f, 100.f)); // on the target's rim
}

TEST(SweepCircleVsCircle, AnOffCentreHitHasTheCentreToCentreNormal)
{
    // Moving right along y = 100 - 15: first touch when the centres are 30 apart, with the
    // centre at x = 100 - sqrt(30^2 - 15^2).
    const Circle mover{{0.f, 85.f}, 10.f};
    const Hit hit = sweepCircleVsCircle(mover, {200.f, 0.f}, ball);
    ASSERT_TRUE(hit);
    const float touchX = 100.f - std::sqrt(30.f * 30.f - 15.f * 15.f);
    EXPECT_NEAR(hit.time, touchX / 200.f, 1e-6f);
    expectNear(hit.normal, hitbox::Vec2(touchX - 100.f, -15.f) / 30.f);
}

TEST(SweepCircleVsCircle, TouchingAndMovingAwayOrAlongMisses)
{
    const Circle touching{{70.f, 100.f}, 10.f};
    EXPECT_FALSE(sweepCircleVsCircle(touching, {-50.f, 0.f}, ball));
    EXPECT_FALSE(sweepCircleVsCircle(touching, {0.f, 50.f}, ball)); // along the tangent
}

TEST(SweepCircleVsCircle, TouchingAndMovingInHitsAtTimeZero)
{
    const Hit hit = sweepCircleVsCircle(Circle{{70.f, 100.f}, 10.f}, {5.f, 1.f}, ball);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
}

TEST(SweepCircleVsCircle, StartingOverlappedReportsThePushOut)
{
    const Hit hit = sweepCircleVsCircle(Circle{{75.f, 100.f}, 10.f}, {-100.f, 0.f}, ball);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(hit.depth, 5.f);
}

TEST(SweepCircleVsCircle, ZeroDisplacementIsTheDiscreteTest)
{
    EXPECT_FALSE(sweepCircleVsCircle(Circle{{0.f, 0.f}, 10.f}, {0.f, 0.f}, ball));
    EXPECT_FALSE(sweepCircleVsCircle(Circle{{70.f, 100.f}, 10.f}, {0.f, 0.f}, ball)); // touching
    EXPECT_TRUE(sweepCircleVsCircle(Circle{{75.f, 100.f}, 10.f}, {0.f, 0.f}, ball).startedInside);
}

TEST(SweepCircleVsCircle, TwoPointsNeverHit)
{
    EXPECT_FALSE(
        sweepCircleVsCircle(Circle{{0.f, 0.f}, 0.f}, {10.f, 0.f}, Circle{{5.f, 0.f}, 0.f}));
}

TEST(SweepCircleVsCircle, IsSymmetricAndTranslationInvariant)
{
    // Swapping mover and target (and reversing the move) gives the same time and the
    // opposite normal; moving the whole scene changes nothing.
    std::mt19937 random(7u);
    std::uniform_real_distribution<float> coordinate(-200.f, 200.f);
    std::uniform_real_distribution<float> size(1.f, 40.f);
    int hits = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const Circle a{{coordinate(random), coordinate(random)}, size(random)};
        const Circle b{{coordinate(random), coordinate(random)}, size(random)};
        const hitbox::Vec2 move(coordinate(random) * 2.f, coordinate(random) * 2.f);
        const Hit forward = sweepCircleVsCircle(a, move, b);
        const Hit backward = sweepCircleVsCircle(b, -move, a);
        ASSERT_EQ(forward.hit, backward.hit);
        const hitbox::Vec2 shift(std::round(coordinate(random)) * 4.f,
                                 std::round(coordinate(random)) * 4.f);
        const Hit shifted = sweepCircleVsCircle(Circle{a.center + shift, a.radius}, move,
                                                Circle{b.center + shift, b.radius});
        ASSERT_EQ(forward.hit, shifted.hit);
        if (!forward.hit)
            continue;
        ++hits;
        EXPECT_NEAR(forward.time, backward.time, 1e-5f);
        EXPECT_NEAR(forward.time, shifted.time, 1e-5f);
        if (!forward.startedInside)
            expectNear(forward.normal, -backward.normal, 1e-4f);
    }
    EXPECT_GT(hits, 1000);
}

// ---- both circles moving -----------------------------------------------------------------

TEST(SweepCircleVsMovingCircle, HeadOnBallsMeetInTheMiddle)
{
    const Circle left{{0.f, 0.f}, 10.f};
    const Circle right{{100.f, 0.f}, 10.f};
    const Hit hit = sweepCircleVsMovingCircle(left, {100.f, 0.f}, right, {-100.f, 0.f});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.4f); // 80 px apart, closing at 200 px per step
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    expectNear(hit.point, {50.f, 0.f}); // both have moved 40 px: they meet at x = 50
}

TEST(SweepCircleVsMovingCircle, MovingTogetherNeverHits)
{
    const Circle leader{{50.f, 0.f}, 10.f};
    const Circle follower{{0.f, 0.f}, 10.f};
    EXPECT_FALSE(sweepCircleVsMovingCircle(follower, {500.f, 0.f}, leader, {500.f, 0.f}));
}

TEST(SweepCircleVsMovingCircle, ACrossingThatASnapshotMissesIsFound)
{
    // Each ball jumps across the other's path in one step: start and end are far apart,
    // but halfway through they pass through each other.
    const Circle a{{-100.f, 0.f}, 5.f};
    const Circle b{{100.f, 0.f}, 5.f};
    const Hit hit = sweepCircleVsMovingCircle(a, {200.f, 0.f}, b, {-200.f, 0.f});
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hitbox::circleVsCircle(Circle{{100.f, 0.f}, 5.f}, Circle{{-100.f, 0.f}, 5.f}));
    EXPECT_NEAR(hit.time, 190.f / 400.f, 1e-6f);
}

// ---- circle vs box (the rounded box) -----------------------------------------------------

TEST(SweepCircleVsBox, HitsAFaceAndStopsTouchingIt)
{
    const Hit hit = sweepCircleVsBox(Circle{{0.f, 50.f}, 10.f}, {200.f, 0.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.45f); // centre at x = 90
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(hit.point, hitbox::Vec2(100.f, 50.f));

    const Hit fromBelow = sweepCircleVsBox(Circle{{120.f, 200.f}, 10.f}, {0.f, -200.f}, wall);
    ASSERT_TRUE(fromBelow);
    EXPECT_FLOAT_EQ(fromBelow.time, 0.45f);
    EXPECT_EQ(fromBelow.normal, hitbox::Vec2(0.f, 1.f));
}

TEST(SweepCircleVsBox, HitsARoundedCornerWithTheCornerToCentreNormal)
{
    // Straight at the top-left corner (100, 0) along the diagonal: first touch when the
    // centre is 10 px from the corner, and the normal points from the corner to the centre.
    const Hit hit = sweepCircleVsBox(Circle{{70.f, -30.f}, 10.f}, {40.f, 40.f}, wall);
    ASSERT_TRUE(hit);
    const float travelled = 30.f * std::sqrt(2.f) - 10.f;
    EXPECT_NEAR(hit.time, travelled / (40.f * std::sqrt(2.f)), 1e-6f);
    expectNear(hit.normal, {-diagonal, -diagonal});
    expectNear(hit.point, {100.f, 0.f});
}

TEST(SweepCircleVsBox, PassingTheCornerOutsideTheRoundingMisses)
{
    // This path crosses the square corner of the box grown by the radius, but stays 12 px
    // from the real corner: a square-cornered Minkowski box would report a false hit.
    const float offset = 12.f * std::sqrt(2.f);
    const Hit hit = sweepCircleVsBox(Circle{{60.f, 40.f - offset}, 10.f}, {60.f, -60.f}, wall);
    EXPECT_FALSE(hit);
}

TEST(SweepCircleVsBox, GrazingAFaceMisses)
{
    // Sliding along the top face, exactly touching it.
    EXPECT_FALSE(sweepCircleVsBox(Circle{{50.f, -10.f}, 10.f}, {200.f, 0.f}, wall));
}

TEST(SweepCircleVsBox, StartingOverlappedReportsThePushOut)
{
    // Centre 5 px left of the wall, radius 10: 5 px into it.
    const Hit hit = sweepCircleVsBox(Circle{{95.f, 50.f}, 10.f}, {-100.f, 0.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(hit.depth, 5.f);
}

TEST(SweepCircleVsBox, ZeroRadiusIsTheSegmentTest)
{
    const Hit circle = sweepCircleVsBox(Circle{{0.f, 50.f}, 0.f}, {200.f, 0.f}, wall);
    const Hit segment = hitbox::segmentVsBox({0.f, 50.f}, {200.f, 50.f}, wall);
    ASSERT_TRUE(circle);
    EXPECT_EQ(circle.time, segment.time);
    EXPECT_EQ(circle.normal, segment.normal);
    EXPECT_FALSE(sweepCircleVsBox(Circle{{0.f, 0.f}, 0.f}, {200.f, 0.f}, wall)); // along an edge
    // Passing just left of a corner (checked with exact fractions): the segment test misses,
    // so the zero-radius circle must too (its corner circles have no area).
    const hitbox::Box box(37.2179489f, 19.766571f, 41.850708f, 12.6833782f);
    const hitbox::Vec2 start(28.6879559f, 101.916504f), move(10.1210279f, -97.4727402f);
    EXPECT_FALSE(hitbox::segmentVsBox(start, start + move, box));
    EXPECT_FALSE(sweepCircleVsBox(Circle{start, 0.f}, move, box));
}

TEST(SweepCircleVsBox, ZeroSizeBoxIsAPointToHit)
{
    const hitbox::Box point(100.f, 100.f, 0.f, 0.f);
    const Hit box = sweepCircleVsBox(Circle{{0.f, 100.f}, 10.f}, {200.f, 0.f}, point);
    const Hit circle =
        sweepCircleVsCircle(Circle{{0.f, 100.f}, 10.f}, {200.f, 0.f}, Circle{{100.f, 100.f}, 0.f});
    ASSERT_TRUE(box);
    EXPECT_FLOAT_EQ(box.time, circle.time);
    EXPECT_EQ(box.normal, circle.normal);
    // A point moving through a point shares no area.
    EXPECT_FALSE(sweepCircleVsBox(Circle{{0.f, 100.f}, 0.f}, {200.f, 0.f}, point));
}

TEST(SweepCircleVsBox, NegativeSizeBoxIsReadAsSfmlDoes)
{
    const hitbox::Box flipped(150.f, 100.f, -50.f, -100.f); // the same box as `wall`
    const Hit hit = sweepCircleVsBox(Circle{{0.f, 50.f}, 10.f}, {200.f, 0.f}, flipped);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.45f);
}

TEST(SweepCircleVsBox, NegativeRadiusNaNOrInfinityNeverHits)
{
    EXPECT_FALSE(sweepCircleVsBox(Circle{{0.f, 50.f}, -1.f}, {200.f, 0.f}, wall));
    EXPECT_FALSE(sweepCircleVsBox(Circle{{0.f, 50.f}, 10.f}, {notANumber, 0.f}, wall));
    EXPECT_FALSE(
        sweepCircleVsBox(Circle{{0.f, 50.f}, 10.f}, {200.f, 0.f}, {0.f, 0.f, infinity, 1.f}));
}

// ---- the fast-mover guarantee ------------------------------------------------------------

TEST(SweptTests, NeverMissACrossingOfAOnePixelWallAtAnySpeedUpTo1e6PixelsPerSecond)
{
    // A 1 px wall; movers fired at it from the left at speeds from 1 px/s to 10^6 px/s and
    // angles up to 60 degrees off the normal, one 1/120 s step each, always far enough to
    // end beyond the wall. Every sweep must hit, at the time the mover reaches the wall.
    const hitbox::Box paper(500.f, -1000.f, 1.f, 2000.f);
    const float dt = 1.f / 120.f;
    std::mt19937 random(11u);
    std::uniform_real_distribution<float> angle(-1.047f, 1.047f);
    int tested = 0;
    for (float speed = 1.f; speed <= 1.0e6f; speed *= 1.05f)
    {
        for (int k = 0; k < 8; ++k)
        {
            const float heading = angle(random);
            const hitbox::Vec2 move(speed * dt * std::cos(heading), speed * dt * std::sin(heading));
            // Start so that the leading edge reaches x = 500, at y = 0, somewhere in the step.
            const float before = std::uniform_real_distribution<float>(0.01f, 0.99f)(random);
            const hitbox::Vec2 start(500.f - before * move.x, -before * move.y);
            if (!(move.x > 2.f)) // too slow to get across the wall in one step
                continue;
            ++tested;
            const Hit segment = hitbox::segmentVsBox(start, start + move, paper);
            ASSERT_TRUE(segment) << "segment at " << speed << " px/s";
            EXPECT_NEAR(start.x + segment.time * move.x, 500.f, 1e-3f + 1e-7f * move.x);

            const hitbox::Box bullet(start.x - 4.f, start.y - 2.f, 4.f, 4.f);
            const Hit box = hitbox::sweepBoxVsBox(bullet, move, paper);
            ASSERT_TRUE(box) << "box at " << speed << " px/s";
            EXPECT_EQ(box.normal, hitbox::Vec2(-1.f, 0.f));

            const Hit round = sweepCircleVsBox(Circle{{start.x - 3.f, start.y}, 3.f}, move, paper);
            ASSERT_TRUE(round) << "circle at " << speed << " px/s";
            EXPECT_EQ(round.normal, hitbox::Vec2(-1.f, 0.f));

            // A 1 px ball standing in the way of a 1 px ball.
            const Hit balls =
                sweepCircleVsCircle(Circle{{start.x - 0.5f, 0.f}, 0.5f}, hitbox::Vec2(move.x, 0.f),
                                    Circle{{500.5f, 0.f}, 0.5f});
            ASSERT_TRUE(balls) << "balls at " << speed << " px/s";
        }
    }
    EXPECT_GT(tested, 1000);
}
