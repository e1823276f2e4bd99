// SweepTest.cpp - rays, segments and moving boxes (Sweep.h): the edge rules, one test each.
#include "hitbox/geometry/Sweep.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using hitbox::Hit;
using hitbox::segmentVsBox;
using hitbox::sweepBoxVsBox;
using hitbox::sweepBoxVsMovingBox;

namespace
{
const hitbox::Box wall(100.f, 0.f, 50.f, 100.f); // x 100..150, y 0..100
const float notANumber = std::numeric_limits<float>::quiet_NaN();
const float infinity = std::numeric_limits<float>::infinity();
} // namespace

// ---- segment vs box (the slab method) ----

TEST(SegmentVsBox, HitsTheNearFaceFromEachSide)
{
    const Hit fromLeft = segmentVsBox({0.f, 50.f}, {200.f, 50.f}, wall);
    ASSERT_TRUE(fromLeft);
    EXPECT_FLOAT_EQ(fromLeft.time, 0.5f);
    EXPECT_EQ(fromLeft.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(fromLeft.point, hitbox::Vec2(100.f, 50.f));
    EXPECT_FALSE(fromLeft.startedInside);

    const Hit fromRight = segmentVsBox({250.f, 50.f}, {50.f, 50.f}, wall);
    ASSERT_TRUE(fromRight);
    EXPECT_FLOAT_EQ(fromRight.time, 0.5f);
    EXPECT_EQ(fromRight.normal, hitbox::Vec2(1.f, 0.f));

    const Hit fromAbove = segmentVsBox({120.f, -100.f}, {120.f, 100.f}, wall);
    ASSERT_TRUE(fromAbove);
    EXPECT_FLOAT_EQ(fromAbove.time, 0.5f);
    EXPECT_EQ(fromAbove.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_EQ(fromAbove.point, hitbox::Vec2(120.f, 0.f));

    const Hit fromBelow = segmentVsBox({120.f, 200.f}, {120.f, 0.f}, wall);
    ASSERT_TRUE(fromBelow);
    EXPECT_FLOAT_EQ(fromBelow.time, 0.5f);
    EXPECT_EQ(fromBelow.normal, hitbox::Vec2(0.f, 1.f));
}

TEST(SegmentVsBox, StoppingShortOfTheBoxMisses)
{
    EXPECT_FALSE(segmentVsBox({0.f, 50.f}, {99.f, 50.f}, wall));
}

TEST(SegmentVsBox, EndingExactlyOnTheEdgeMisses)
{
    // It reaches the edge only at time 1: it never gets inside.
    EXPECT_FALSE(segmentVsBox({0.f, 50.f}, {100.f, 50.f}, wall));
}

TEST(SegmentVsBox, ParallelOutsideTheSlabMissesWithoutNaN)
{
    // Horizontal ray above the box: the y slab is never entered (0 / 0 = NaN).
    const Hit above = segmentVsBox({0.f, -10.f}, {300.f, -10.f}, wall);
    EXPECT_FALSE(above);
    EXPECT_FALSE(std::isnan(above.time));
}

TEST(SegmentVsBox, ParallelAlongAnEdgeMisses)
{
    // Exactly along the top edge: on the edge is not inside.
    EXPECT_FALSE(segmentVsBox({0.f, 0.f}, {300.f, 0.f}, wall));
    EXPECT_FALSE(segmentVsBox({100.f, -50.f}, {100.f, 200.f}, wall));
}

TEST(SegmentVsBox, ParallelInsideTheSlabHits)
{
    const Hit hit = segmentVsBox({0.f, 10.f}, {300.f, 10.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 100.f / 300.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
}

TEST(SegmentVsBox, StartingInsideReportsThePushOut)
{
    const Hit hit = segmentVsBox({110.f, 50.f}, {300.f, 50.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f)); // nearest edge is the left one
    EXPECT_FLOAT_EQ(hit.depth, 10.f);
    EXPECT_EQ(hit.point, hitbox::Vec2(100.f, 50.f));
}

TEST(SegmentVsBox, StartingOnTheEdgeAndGoingInHitsAtTimeZero)
{
    const Hit hit = segmentVsBox({100.f, 50.f}, {200.f, 50.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
}

TEST(SegmentVsBox, StartingOnTheEdgeAndGoingAwayMisses)
{
    EXPECT_FALSE(segmentVsBox({100.f, 50.f}, {0.f, 50.f}, wall));
}

TEST(SegmentVsBox, ExactCornerHitGivesTheXNormal)
{
    // Diagonal straight into the top-left corner (100, 0): both slabs entered at t = 0.5.
    const Hit hit = segmentVsBox({50.f, -50.f}, {150.f, 50.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.5f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(hit.point, hitbox::Vec2(100.f, 0.f));
}

TEST(SegmentVsBox, GrazingACornerMisses)
{
    // Passes through the corner (100, 0) from outside to outside: never inside.
    EXPECT_FALSE(segmentVsBox({50.f, 50.f}, {150.f, -50.f}, wall));
}

TEST(SegmentVsBox, ZeroLengthIsAPointTest)
{
    const Hit inside = segmentVsBox({120.f, 50.f}, {120.f, 50.f}, wall);
    ASSERT_TRUE(inside);
    EXPECT_TRUE(inside.startedInside);
    EXPECT_FALSE(segmentVsBox({0.f, 0.f}, {0.f, 0.f}, wall));
    EXPECT_FALSE(segmentVsBox({100.f, 50.f}, {100.f, 50.f}, wall)); // on the edge
}

TEST(SegmentVsBox, ZeroSizeBoxIsNeverHit)
{
    EXPECT_FALSE(segmentVsBox({0.f, 5.f}, {20.f, 5.f}, hitbox::Box(10.f, 5.f, 0.f, 0.f)));
    EXPECT_FALSE(segmentVsBox({0.f, 5.f}, {20.f, 5.f}, hitbox::Box(10.f, 0.f, 0.f, 10.f)));
}

TEST(SegmentVsBox, NegativeSizeBoxIsReadAsSfmlDoes)
{
    const hitbox::Box flipped(150.f, 100.f, -50.f, -100.f); // the same box as `wall`
    const Hit hit = segmentVsBox({0.f, 50.f}, {200.f, 50.f}, flipped);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.5f);
}

TEST(SegmentVsBox, NaNOrInfiniteInputNeverHits)
{
    EXPECT_FALSE(segmentVsBox({notANumber, 50.f}, {200.f, 50.f}, wall));
    EXPECT_FALSE(segmentVsBox({0.f, 50.f}, {infinity, 50.f}, wall));
    EXPECT_FALSE(segmentVsBox({0.f, 50.f}, {200.f, 50.f}, hitbox::Box(notANumber, 0.f, 1.f, 1.f)));
}

// ---- box sweeps ----

TEST(SweepBoxVsBox, StopsTouchingTheWall)
{
    const hitbox::Box mover(0.f, 40.f, 20.f, 20.f);
    const Hit hit = sweepBoxVsBox(mover, {160.f, 0.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 80.f / 160.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(hit.point, hitbox::Vec2(100.f, 50.f)); // middle of the touching edge
}

TEST(SweepBoxVsBox, SlidingAlongASurfaceWhileTouchingMisses)
{
    const hitbox::Box onTop(110.f, -20.f, 20.f, 20.f); // resting on the wall's top
    EXPECT_FALSE(sweepBoxVsBox(onTop, {30.f, 0.f}, wall));
    EXPECT_FALSE(sweepBoxVsBox(onTop, {-300.f, 0.f}, wall));
}

TEST(SweepBoxVsBox, MovingAwayFromTouchingMisses)
{
    const hitbox::Box onTop(110.f, -20.f, 20.f, 20.f);
    EXPECT_FALSE(sweepBoxVsBox(onTop, {5.f, -10.f}, wall));
}

TEST(SweepBoxVsBox, MovingIntoASurfaceFromTouchingHitsAtTimeZero)
{
    const hitbox::Box onTop(110.f, -20.f, 20.f, 20.f);
    const Hit hit = sweepBoxVsBox(onTop, {10.f, 5.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FALSE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(0.f, -1.f));
}

TEST(SweepBoxVsBox, StartingOverlappedReportsThePushOut)
{
    const hitbox::Box mover(95.f, 40.f, 20.f, 20.f); // 15 px into the wall's left side
    const Hit hit = sweepBoxVsBox(mover, {-50.f, 0.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_TRUE(hit.startedInside);
    EXPECT_EQ(hit.time, 0.f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(hit.depth, 15.f);
}

TEST(SweepBoxVsBox, ExactCornerHitGivesTheXNormal)
{
    const hitbox::Box mover(60.f, -40.f, 20.f, 20.f); // bottom-right corner at (80, -20)
    const Hit hit = sweepBoxVsBox(mover, {40.f, 40.f}, wall);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.5f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_EQ(hit.point, hitbox::Vec2(100.f, 0.f));
}

TEST(SweepBoxVsBox, ZeroDisplacementIsTheDiscreteTest)
{
    EXPECT_FALSE(sweepBoxVsBox({0.f, 0.f, 10.f, 10.f}, {0.f, 0.f}, wall));
    EXPECT_FALSE(sweepBoxVsBox({90.f, 0.f, 10.f, 10.f}, {0.f, 0.f}, wall)); // touching
    const Hit inside = sweepBoxVsBox({95.f, 0.f, 10.f, 10.f}, {0.f, 0.f}, wall);
    ASSERT_TRUE(inside);
    EXPECT_TRUE(inside.startedInside);
}

TEST(SweepBoxVsBox, NaNInputNeverHits)
{
    EXPECT_FALSE(sweepBoxVsBox({0.f, 40.f, 20.f, 20.f}, {notANumber, 0.f}, wall));
    EXPECT_FALSE(sweepBoxVsBox({0.f, 40.f, notANumber, 20.f}, {160.f, 0.f}, wall));
}

TEST(SweepBoxVsBox, AFastMoverNeverJumpsAThinWall)
{
    const hitbox::Box paper(500.f, 0.f, 1.f, 100.f);
    const hitbox::Box bullet(0.f, 45.f, 4.f, 4.f);
    const Hit hit = sweepBoxVsBox(bullet, {1.0e6f / 120.f, 0.f}, paper);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
}

TEST(SweepBoxVsMovingBox, HeadOnBoxesMeetInTheMiddle)
{
    const hitbox::Box left(0.f, 0.f, 10.f, 10.f);
    const hitbox::Box right(90.f, 0.f, 10.f, 10.f);
    const Hit hit = sweepBoxVsMovingBox(left, {50.f, 0.f}, right, {-50.f, 0.f});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit.time, 0.8f);
    EXPECT_EQ(hit.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(hit.point.x, 50.f); // both have moved 40 px: they meet at x = 50
}

TEST(SweepBoxVsMovingBox, MovingTogetherNeverHits)
{
    const hitbox::Box leader(20.f, 0.f, 10.f, 10.f);
    const hitbox::Box follower(0.f, 0.f, 10.f, 10.f);
    EXPECT_FALSE(sweepBoxVsMovingBox(follower, {500.f, 0.f}, leader, {500.f, 0.f}));
}
