// GeometryRangeTest.cpp - the edge rule helper and the stated range (Range.h): far-away,
// huge, tiny and many-cornered shapes each get their documented answer, one test each.
// The sweep over the whole range is in tests/long/RangeSweepTest.cpp.
#include "hitbox/geometry/Capsule.h"
#include "hitbox/geometry/Explain.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Resolve.h"
#include "hitbox/geometry/Response.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/geometry/SweptCircle.h"
#include "hitbox/geometry/Vec2.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using hitbox::Capsule;
using hitbox::Circle;
using hitbox::Contact;
using hitbox::OrientedBox;
using hitbox::Polygon;
using hitbox::toPolygon;

namespace
{
const float notANumber = std::numeric_limits<float>::quiet_NaN();

// What every hit must be, in or out of range: depth > 0 and finite, unit normal, finite point.
void expectWellFormed(const Contact& contact)
{
    if (!contact.hit)
        return;
    EXPECT_TRUE(std::isfinite(contact.depth) && contact.depth > 0.f) << contact.depth;
    EXPECT_NEAR(hitbox::length(contact.normal), 1.f, 1e-6f)
        << ::testing::PrintToString(contact.normal);
    EXPECT_TRUE(hitbox::isFinite(contact.point)) << ::testing::PrintToString(contact.point);
}

// A regular polygon with `corners` corners round `centre`.
Polygon regularPolygon(hitbox::Vec2 centre, float radius, int corners)
{
    Polygon polygon;
    for (int k = 0; k < corners; ++k)
    {
        const double angle = 2.0 * hitbox::piDouble * k / corners;
        polygon.points.push_back(centre +
                                 hitbox::Vec2(static_cast<float>(radius * std::cos(angle)),
                                              static_cast<float>(radius * std::sin(angle))));
    }
    return polygon;
}
} // namespace

// ---- the edge rule, in one place (Shapes.h) -----------------------------------------------

TEST(GeometryEdgeRule, OnlyAPositiveDepthPenetrates)
{
    EXPECT_TRUE(hitbox::penetrates(1e-45f)); // the smallest float still shares area
    EXPECT_FALSE(hitbox::penetrates(0.f));   // touching
    EXPECT_FALSE(hitbox::penetrates(-0.f));
    EXPECT_FALSE(hitbox::penetrates(-3.f)); // a gap
    EXPECT_FALSE(hitbox::penetrates(notANumber));
    EXPECT_TRUE(hitbox::penetrates(std::numeric_limits<float>::infinity()));
}

TEST(GeometryEdgeRule, SpansWithNaNNeverOverlap)
{
    EXPECT_TRUE(hitbox::spansOverlap(0.f, 2.f, 1.f, 3.f));
    EXPECT_FALSE(hitbox::spansOverlap(0.f, 1.f, 1.f, 3.f)); // touching
    EXPECT_FALSE(hitbox::spansOverlap(notANumber, 2.f, 1.f, 3.f));
    EXPECT_FALSE(hitbox::spansOverlap(0.f, notANumber, 1.f, 3.f));
    EXPECT_FALSE(hitbox::spansOverlap(0.f, 2.f, notANumber, 3.f));
    EXPECT_FALSE(hitbox::spansOverlap(0.f, 2.f, 1.f, notANumber));
}

// ---- the range (Range.h) ------------------------------------------------------------------

TEST(GeometryRange, TheEdgesOfTheRangeAreIn)
{
    EXPECT_TRUE(hitbox::withinExactRange(hitbox::exactRange));
    EXPECT_TRUE(hitbox::withinExactRange(-hitbox::exactRange));
    EXPECT_TRUE(hitbox::withinExactRange(1e-45f));
    EXPECT_FALSE(hitbox::withinExactRange(std::nextafter(hitbox::exactRange, 2e6f)));
    EXPECT_FALSE(hitbox::withinExactRange(notANumber));
    EXPECT_FALSE(hitbox::withinExactRange(std::numeric_limits<float>::infinity()));
}

TEST(GeometryRange, ShapesAt1e20NeverCollideInsteadOfANaNDepth)
{
    // Before: hit, depth NaN.
    const Contact boxes =
        hitbox::orientedBoxVsOrientedBox(OrientedBox{{1e20f, 1e20f}, {1e18f, 1e18f}, 30.f},
                                         OrientedBox{{1e20f, 1e20f}, {1e18f, 1e18f}, 0.f});
    EXPECT_FALSE(boxes);
    const Contact polygons =
        hitbox::polygonVsPolygon(toPolygon(hitbox::Box(1e20f, 1e20f, 1e19f, 1e19f)),
                                 toPolygon(OrientedBox{{1e20f, 1e20f}, {1e19f, 1e19f}, 10.f}));
    EXPECT_FALSE(polygons);
    // The same shapes scaled into the range do collide.
    EXPECT_TRUE(hitbox::orientedBoxVsOrientedBox(OrientedBox{{1e5f, 1e5f}, {1e3f, 1e3f}, 30.f},
                                                 OrientedBox{{1e5f, 1e5f}, {1e3f, 1e3f}, 0.f}));
}

TEST(GeometryRange, APointAgainstASegment1e20LongNeverCollides)
{
    // Before: hit, with normal and depth NaN. Two shapes with no area never collide, and
    // the segment is out of range anyway.
    const Polygon longSegment{{{-1e20f, -1e20f}, {1e20f, 1e20f}}};
    EXPECT_FALSE(hitbox::polygonVsPolygon(Polygon{{{5.f, 3.f}}}, longSegment));
    EXPECT_FALSE(hitbox::polygonVsPolygon(longSegment, Polygon{{{5.f, 3.f}}}));
    // In range, the same point and segment still never collide: neither has area.
    const Polygon segment{{{-1e6f, -1e6f}, {1e6f, 1e6f}}};
    EXPECT_FALSE(hitbox::polygonVsPolygon(Polygon{{{5.f, 5.f}}}, segment));
    EXPECT_FALSE(hitbox::polygonVsPolygon(Polygon{{{5.f, 3.f}}}, segment));
}

TEST(GeometryRange, ABoxFarFromAHugeBoxIsNotHitByRounding)
{
    // A 2 x 2 box 142 px above a box 1e10 px long: outside the range, so no hit.
    const OrientedBox small{{100.f, -143.f}, {1.f, 1.f}, 45.f};
    EXPECT_FALSE(
        hitbox::orientedBoxVsOrientedBox(small, OrientedBox{{0.f, 0.f}, {5e9f, 1.f}, 30.f}));
    // A box 8e5 px long, turned the same way, reaching +-3.5e5 px: the range promises answers
    // within 1e-6 of that (0.35 px), so a 0.5 px gap and a 0.5 px overlap are both seen.
    const float angle = 30.f;
    const float radians = angle * hitbox::pi / 180.f;
    const hitbox::Vec2 across(-std::sin(radians), std::cos(radians));
    const OrientedBox longBox{{0.f, 0.f}, {4e5f, 1.f}, angle};
    const float tolerance = 1e-6f * 3.5e5f;
    EXPECT_FALSE(
        hitbox::orientedBoxVsOrientedBox(OrientedBox{across * -2.5f, {1.f, 1.f}, angle}, longBox));
    const Contact contact =
        hitbox::orientedBoxVsOrientedBox(OrientedBox{across * -1.5f, {1.f, 1.f}, angle}, longBox);
    ASSERT_TRUE(contact);
    EXPECT_NEAR(contact.depth, 0.5f, tolerance);
    expectWellFormed(contact);
}

TEST(GeometryRange, ADenormalCentreGetsAUnitNormal)
{
    // Before: normal (1, 1).
    const Polygon corner{{{0.f, 0.f}, {0.f, -10.f}, {-10.f, 0.f}}};
    const Contact contact = hitbox::circleVsPolygon(Circle{{1e-45f, 1e-45f}, 1.f}, corner);
    ASSERT_TRUE(contact);
    EXPECT_NEAR(contact.normal.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(contact.normal.y, std::sqrt(0.5f), 1e-6f);
    EXPECT_FLOAT_EQ(contact.depth, 1.f);
    expectWellFormed(contact);
}

TEST(GeometryRange, AZeroRadiusCircleWhoseWayOutRoundsToZeroIsTouching)
{
    // A point next to a triangle's edge that the inside test puts inside but whose distance
    // to the edge rounds to 0. Before: hit with depth 0. Now: touching, not a hit.
    const Polygon triangle{
        {{-66.0339203f, -88.1513596f}, {75.6284943f, 34.1056061f}, {-80.3306351f, 18.6130981f}}};
    const Contact contact =
        hitbox::circleVsPolygon(Circle{{-6.37879992f, -36.6680183f}, 0.f}, triangle);
    EXPECT_FALSE(contact) << contact.depth;
    // A point clearly inside still collides, with its way out as the depth.
    const Contact inside = hitbox::circleVsPolygon(Circle{{-20.f, 0.f}, 0.f}, triangle);
    ASSERT_TRUE(inside);
    expectWellFormed(inside);
}

TEST(GeometryRange, OutOfRangeCirclesAndCapsulesNeverCollide)
{
    const Polygon square = toPolygon(hitbox::Box(0.f, 0.f, 10.f, 10.f));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{5.f, 5.f}, 2e6f}, square));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{5.f, 5.f}, 2.f},
                                         toPolygon(hitbox::Box(0.f, 0.f, 1e7f, 10.f))));
    EXPECT_FALSE(hitbox::capsuleVsCircle(Capsule{{-1e20f, 0.f}, {1e20f, 0.f}, 1.f},
                                         Circle{{0.f, 0.f}, 1.f}));
    EXPECT_FALSE(hitbox::capsuleVsCapsule(Capsule{{0.f, 0.f}, {1.f, 0.f}, 2e6f},
                                          Capsule{{0.f, 0.f}, {1.f, 0.f}, 1.f}));
    EXPECT_FALSE(hitbox::capsuleVsPolygon(Capsule{{0.f, 0.f}, {1e7f, 0.f}, 1.f}, square));
    // The same in range collide.
    EXPECT_TRUE(
        hitbox::capsuleVsCircle(Capsule{{-1e6f, 0.f}, {1e6f, 0.f}, 1.f}, Circle{{0.f, 0.f}, 1.f}));
    EXPECT_TRUE(hitbox::capsuleVsPolygon(Capsule{{0.f, 0.f}, {1e6f, 0.f}, 1.f}, square));
}

TEST(GeometryRange, CollinearCornersDoNotChangeTheAnswer)
{
    // Extra corners along the edges (the walks must step over them).
    const Polygon plain = toPolygon(hitbox::Box(0.f, 0.f, 40.f, 40.f));
    const Polygon dotted{{{0.f, 0.f},
                          {0.f, 10.f},
                          {0.f, 20.f},
                          {0.f, 40.f},
                          {20.f, 40.f},
                          {40.f, 40.f},
                          {40.f, 30.f},
                          {40.f, 0.f},
                          {30.f, 0.f},
                          {10.f, 0.f}}};
    const Polygon crate = toPolygon(OrientedBox{{38.f, 20.f}, {5.f, 5.f}, 20.f});
    const Contact expected = hitbox::polygonVsPolygon(crate, plain);
    const Contact actual = hitbox::polygonVsPolygon(crate, dotted);
    ASSERT_TRUE(expected);
    ASSERT_TRUE(actual);
    EXPECT_EQ(actual.normal, expected.normal);
    EXPECT_EQ(actual.depth, expected.depth);
    // A segment written with extra points in line, out of order, is still a segment.
    EXPECT_FALSE(hitbox::polygonVsPolygon(Polygon{{{5.f, 5.f}}},
                                          Polygon{{{0.f, 0.f}, {10.f, 10.f}, {3.f, 3.f}}}));
}

// ---- many corners: O(n + m) ---------------------------------------------------------------

TEST(PolygonVsPolygon, AHundredThousandGonAgainstASquare)
{
    // Before: O(n^2), a 10^4-gon took seconds and a 10^5-gon minutes. The figures are in
    // tests/benchmarks/PolygonBench.cpp; here only the answers.
    const Polygon wheel = regularPolygon({0.f, 0.f}, 1000.f, 100000);
    const Polygon square = toPolygon(hitbox::Box(990.f, -5.f, 20.f, 10.f));
    const Contact contact = hitbox::polygonVsPolygon(square, wheel);
    ASSERT_TRUE(contact);
    EXPECT_NEAR(contact.depth, 10.f, 1e-3f);
    EXPECT_NEAR(contact.normal.x, 1.f, 1e-6f);
    expectWellFormed(contact);
    EXPECT_FALSE(hitbox::polygonVsPolygon(toPolygon(hitbox::Box(1001.f, -5.f, 20.f, 10.f)), wheel));
    const Contact circle = hitbox::circleVsPolygon(Circle{{1005.f, 0.f}, 10.f}, wheel);
    ASSERT_TRUE(circle);
    EXPECT_NEAR(circle.depth, 5.f, 1e-3f);
    // Capsule against the wheel, O(n) as well: its left round end reaches 4 px in, then 6 px out.
    const Contact stick =
        hitbox::capsuleVsPolygon(Capsule{{1020.f, 0.f}, {1060.f, 0.f}, 24.f}, wheel);
    ASSERT_TRUE(stick);
    EXPECT_NEAR(stick.depth, 4.f, 1e-3f);
    EXPECT_NEAR(stick.normal.x, 1.f, 1e-6f);
    expectWellFormed(stick);
    EXPECT_FALSE(hitbox::capsuleVsPolygon(Capsule{{1030.f, 0.f}, {1070.f, 0.f}, 24.f}, wheel));
}

// ---- every test works on the convex hull --------------------------------------------------

TEST(ConvexHull, StartsAtTheLeftmostCornerAndGoesClockwiseOnScreen)
{
    // Points in any order, one repeated, one in a dent, one on an edge.
    const Polygon scattered{
        {{10.f, 10.f}, {0.f, 0.f}, {10.f, 0.f}, {5.f, 2.f}, {0.f, 10.f}, {10.f, 5.f}, {0.f, 0.f}}};
    const Polygon hull = hitbox::convexHull(scattered);
    const std::vector<hitbox::Vec2> expected{{0.f, 0.f}, {10.f, 0.f}, {10.f, 10.f}, {0.f, 10.f}};
    EXPECT_EQ(hull.points, expected);
    EXPECT_GT(hitbox::twiceSignedArea(hull), 0.f); // clockwise on screen
    EXPECT_TRUE(
        hitbox::convexHull(Polygon{{{0.f, 0.f}, {notANumber, 1.f}, {1.f, 1.f}}}).points.empty());
    // All in line: the two ends.
    const std::vector<hitbox::Vec2> ends{{0.f, 0.f}, {3.f, 3.f}};
    EXPECT_EQ(hitbox::convexHull(Polygon{{{1.f, 1.f}, {3.f, 3.f}, {0.f, 0.f}}}).points, ends);
}

TEST(ConvexHull, AConcavePolygonCollidesAsItsHull)
{
    // A "C" shape: a box with a notch cut into its right side. A crate in the notch is
    // inside the hull, so every test reports it.
    const Polygon notched{{{0.f, 0.f},
                           {30.f, 0.f},
                           {30.f, 10.f},
                           {10.f, 10.f},
                           {10.f, 20.f},
                           {30.f, 20.f},
                           {30.f, 30.f},
                           {0.f, 30.f}}};
    const Polygon crate = toPolygon(hitbox::Box(20.f, 12.f, 6.f, 6.f));
    EXPECT_TRUE(hitbox::polygonVsPolygon(crate, notched));
    EXPECT_TRUE(hitbox::circleVsPolygon(Circle{{23.f, 15.f}, 2.f}, notched));
    EXPECT_TRUE(hitbox::capsuleVsPolygon(Capsule{{20.f, 15.f}, {25.f, 15.f}, 2.f}, notched));
    EXPECT_TRUE(hitbox::pointInPolygon({23.f, 15.f}, notched));
}

// Issue 25, item 11: outside the stated range the answer is "no hit", never a wrong hit or
// an infinite depth.
TEST(GeometryRange, CirclesAndSegmentsBeyondTheRangeAreNoHit)
{
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, 1e20f}, {{3e19f, 0.f}, 1e20f}));
    const hitbox::Contact huge =
        hitbox::circleVsCircleContact({{0.f, 0.f}, 2e38f}, {{1.f, 0.f}, 2e38f});
    EXPECT_FALSE(huge.hit) << "depth " << huge.depth;
    EXPECT_FALSE(hitbox::segmentVsBox({-3e38f, 5.f}, {3e38f, 5.f}, {0.f, 0.f, 10.f, 10.f}).hit);
    // Inside the range both still hit.
    EXPECT_TRUE(hitbox::circleVsCircle({{0.f, 0.f}, 1e6f}, {{1e6f, 0.f}, 1e6f}));
    EXPECT_TRUE(hitbox::segmentVsBox({-1e6f, 5.f}, {1e6f, 5.f}, {0.f, 0.f, 10.f, 10.f}).hit);
}

// moveBoxAndSlide (Resolve.h): a move of the whole range is exact; beyond it, no move.
// Before: 3e38 px/s ended at (inf, inf).
TEST(GeometryRange, MoveBoxAndSlideIsExactUpToTheEdgeOfTheRange)
{
    const float edge = hitbox::exactRange;
    const hitbox::Box box(0.f, 0.f, 10.f, 10.f);
    EXPECT_EQ(hitbox::moveBoxAndSlide(box, {edge, -edge}, 1.f, {}).box,
              hitbox::Box(edge, -edge, 10.f, 10.f));
    // A wall half the range away stops it touching, at the edge of the range too.
    const hitbox::Box wall(edge / 2.f, -50.f, 10.f, 100.f);
    const hitbox::MoveResult stopped = hitbox::moveBoxAndSlide(box, {edge, 0.f}, 1.f, {wall});
    EXPECT_EQ(hitbox::rightOf(stopped.box), edge / 2.f);
    EXPECT_EQ(stopped.velocity, hitbox::Vec2(0.f, 0.f));
    // A mover at the edge of the range still moves.
    EXPECT_EQ(hitbox::moveBoxAndSlide({-edge, 0.f, 10.f, 10.f}, {60.f, 0.f}, 0.5f, {}).box.left,
              -edge + 30.f);
}

TEST(GeometryRange, MoveBoxAndSlideBeyondTheRangeDoesNotMove)
{
    const hitbox::Box box(0.f, 0.f, 10.f, 10.f);
    const hitbox::Box wall(100.f, -50.f, 10.f, 100.f);
    for (const hitbox::Vec2 velocity : {hitbox::Vec2(3e38f, 3e38f), hitbox::Vec2(-3e38f, 0.f),
                                        hitbox::Vec2(2.f * hitbox::exactRange, 0.f)})
    {
        const hitbox::MoveResult result = hitbox::moveBoxAndSlide(box, velocity, 1.f, {wall});
        EXPECT_EQ(result.box, box) << velocity.x;
        EXPECT_TRUE(result.hits.empty());
    }
    const hitbox::Box far(2e6f, 0.f, 10.f, 10.f); // beyond the range: stays, no hit
    EXPECT_EQ(hitbox::moveBoxAndSlide(far, {60.f, 0.f}, 1.f, {}).box, far);
    // A solid far larger than the range is still a floor (Sweep.h: any finite box).
    const hitbox::Box hugeFloor(-1e30f, 50.f, 2e30f, 10.f);
    EXPECT_EQ(hitbox::moveBoxAndSlide(box, {0.f, 6000.f}, 1.f / 60.f, {hugeFloor}).box.top, 40.f);
}

// The circle sweeps (SweptCircle.h) take Overlap.h's circle range: in at the edge, out beyond.
TEST(GeometryRange, CircleSweepsHitAtTheEdgeOfTheRangeAndNotBeyond)
{
    const float edge = hitbox::exactRange;
    const Circle atEdge{{edge - 100.f, 0.f}, 10.f};
    const Circle target{{edge, 0.f}, 10.f};
    const hitbox::Hit in = hitbox::sweepCircleVsCircle(atEdge, {100.f, 0.f}, target);
    EXPECT_TRUE(in.hit);
    EXPECT_FLOAT_EQ(in.time, 0.8f);
    EXPECT_TRUE(
        hitbox::sweepCircleVsBox(atEdge, {100.f, 0.f}, {edge - 20.f, -5.f, 10.f, 10.f}).hit);
    // Beyond: no hit, whatever the move (before, radii 2e38 gave an infinite point).
    EXPECT_FALSE(
        hitbox::sweepCircleVsCircle({{2e6f, 0.f}, 10.f}, {100.f, 0.f}, {{2e6f + 50.f, 0.f}, 10.f})
            .hit);
    EXPECT_FALSE(
        hitbox::sweepCircleVsCircle({{0.f, 0.f}, 2e38f}, {1.f, 0.f}, {{3e38f, 0.f}, 2e38f}).hit);
    EXPECT_FALSE(
        hitbox::sweepCircleVsCircle({{0.f, 0.f}, 10.f}, {4e6f, 0.f}, {{2e6f, 0.f}, 10.f}).hit);
}

// The explanations (Explain.h) agree with the test beyond the range and say why.
TEST(GeometryRange, ExplainingCirclesBeyondTheRangeSaysTheyDoNotCollide)
{
    const hitbox::Explanation why =
        hitbox::explainCircles({{0.f, 0.f}, 1e20f}, {{3e19f, 0.f}, 1e20f});
    EXPECT_FALSE(why.collides);
    EXPECT_NE(why.verdict.find("exact range"), std::string::npos) << why.verdict;
    EXPECT_FALSE(hitbox::explainCircleBox({{2e6f, 0.f}, 10.f}, {2e6f, 0.f, 5.f, 5.f}).collides);
}

// The responses (Response.h) are exact at 1e6 px/s, the speed its range states.
TEST(GeometryRange, ResponsesAreExactAtTheStatedSpeed)
{
    const float fast = 1e6f;
    hitbox::Hit floor;
    floor.hit = true;
    floor.time = 0.f;
    floor.normal = {0.f, -1.f};
    EXPECT_EQ(hitbox::slideVelocity({fast, fast}, floor), hitbox::Vec2(fast, 0.f));
    EXPECT_EQ(hitbox::bounceVelocity({fast, fast}, {0.f, -1.f}, 1.f), hitbox::Vec2(fast, -fast));
    const hitbox::VelocityPair swapped =
        hitbox::elasticCollision({fast, 0.f}, 1.f, {-fast, 0.f}, 1.f, {-1.f, 0.f});
    EXPECT_EQ(swapped.first, hitbox::Vec2(-fast, 0.f));
    EXPECT_EQ(swapped.second, hitbox::Vec2(fast, 0.f));
}
