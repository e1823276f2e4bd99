// PointInPolygonTest.cpp - the crossing-number test (PointInPolygon.h): one test per edge rule.
#include "hitbox/geometry/PointInPolygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

using hitbox::pointInPolygon;
using hitbox::PointInPolygonResult;
using hitbox::Polygon;
using hitbox::Vec2;

namespace
{
// A "C" shape, 0..30 wide and 0..30 tall, open on the right between y = 10 and y = 20.
const Polygon cShape{{{0.f, 0.f},
                      {30.f, 0.f},
                      {30.f, 10.f},
                      {10.f, 10.f},
                      {10.f, 20.f},
                      {30.f, 20.f},
                      {30.f, 30.f},
                      {0.f, 30.f}}};
const Polygon square{{{0.f, 0.f}, {10.f, 0.f}, {10.f, 10.f}, {0.f, 10.f}}};

Polygon reversed(Polygon polygon)
{
    std::reverse(polygon.points.begin(), polygon.points.end());
    return polygon;
}
} // namespace

TEST(PointInPolygon, APointInsideASquareIsInside)
{
    const PointInPolygonResult result = pointInPolygon(square, {5.f, 5.f});
    EXPECT_TRUE(result.inside);
    EXPECT_FALSE(result.onEdge);
    EXPECT_EQ(result.crossings, 1);
}

TEST(PointInPolygon, APointOutsideASquareIsOutside)
{
    EXPECT_FALSE(pointInPolygon(square, {15.f, 5.f}).inside);
    EXPECT_FALSE(pointInPolygon(square, {-5.f, 5.f}).inside);
    EXPECT_EQ(pointInPolygon(square, {-5.f, 5.f}).crossings, 2);
    EXPECT_FALSE(pointInPolygon(square, {5.f, -5.f}).inside);
    EXPECT_FALSE(pointInPolygon(square, {5.f, 15.f}).inside);
}

TEST(PointInPolygon, TheNotchOfAConcavePolygonIsOutside)
{
    EXPECT_FALSE(pointInPolygon(cShape, {20.f, 15.f}).inside); // in the notch
    EXPECT_TRUE(pointInPolygon(cShape, {20.f, 5.f}).inside);   // in the top arm
    EXPECT_TRUE(pointInPolygon(cShape, {5.f, 15.f}).inside);   // in the back
    // In the back, the ray to +x crosses only the back edge of the notch; from outside, two.
    EXPECT_EQ(pointInPolygon(cShape, {5.f, 15.f}).crossings, 1);
    EXPECT_EQ(pointInPolygon(cShape, {-5.f, 15.f}).crossings, 2);
}

TEST(PointInPolygon, EitherWindingGivesTheSameAnswer)
{
    for (const Vec2 point : {Vec2{20.f, 15.f}, Vec2{20.f, 5.f}, Vec2{5.f, 15.f}, Vec2{40.f, 5.f}})
        EXPECT_EQ(pointInPolygon(cShape, point).inside,
                  pointInPolygon(reversed(cShape), point).inside);
}

// Edge rule: touching is not colliding.
TEST(PointInPolygon, APointOnAnEdgeIsTouchingNotInside)
{
    for (const Vec2 point : {Vec2{0.f, 5.f}, Vec2{10.f, 5.f}, Vec2{5.f, 0.f}, Vec2{5.f, 10.f}})
    {
        const PointInPolygonResult result = pointInPolygon(square, point);
        EXPECT_FALSE(result.inside) << point.x << ", " << point.y;
        EXPECT_TRUE(result.onEdge) << point.x << ", " << point.y;
    }
    // A slanted edge: the middle of the triangle's long side.
    const Polygon triangle{{{0.f, 0.f}, {10.f, 0.f}, {0.f, 10.f}}};
    EXPECT_TRUE(pointInPolygon(triangle, {5.f, 5.f}).onEdge);
    EXPECT_FALSE(pointInPolygon(triangle, {5.f, 5.f}).inside);
    EXPECT_TRUE(pointInPolygon(triangle, {4.f, 5.f}).inside); // just inside it
}

TEST(PointInPolygon, ACornerIsTouchingNotInside)
{
    for (const Vec2 corner : square.points)
    {
        EXPECT_TRUE(pointInPolygon(square, corner).onEdge);
        EXPECT_FALSE(pointInPolygon(square, corner).inside);
    }
    // The notch's inner corners of the C too.
    EXPECT_TRUE(pointInPolygon(cShape, {10.f, 10.f}).onEdge);
    EXPECT_TRUE(pointInPolygon(cShape, {10.f, 20.f}).onEdge);
}

// The ray from the point runs exactly through corners: each is counted once or not at all.
TEST(PointInPolygon, ARayThroughACornerCountsItOnce)
{
    const Polygon diamond{{{10.f, 0.f}, {20.f, 10.f}, {10.f, 20.f}, {0.f, 10.f}}};
    EXPECT_TRUE(pointInPolygon(diamond, {10.f, 10.f}).inside); // ray passes the right corner
    EXPECT_EQ(pointInPolygon(diamond, {10.f, 10.f}).crossings, 1);
    EXPECT_FALSE(pointInPolygon(diamond, {-5.f, 10.f}).inside); // passes both side corners
    // The ray along the top edge of the C's notch (y = 10), left of the polygon and in it.
    EXPECT_FALSE(pointInPolygon(cShape, {-5.f, 10.f}).inside);
    EXPECT_TRUE(pointInPolygon(cShape, {5.f, 10.f}).inside);
    EXPECT_FALSE(pointInPolygon(cShape, {35.f, 10.f}).inside);
}

TEST(PointInPolygon, ASelfCrossingPolygonUsesTheEvenOddRule)
{
    // A bow tie: two triangles meeting at (5, 5); its signed area is 0, its lobes are inside.
    const Polygon bowTie{{{0.f, 0.f}, {10.f, 10.f}, {10.f, 0.f}, {0.f, 10.f}}};
    EXPECT_TRUE(pointInPolygon(bowTie, {8.f, 5.f}).inside);
    EXPECT_TRUE(pointInPolygon(bowTie, {2.f, 5.f}).inside);
    EXPECT_FALSE(pointInPolygon(bowTie, {5.f, 2.f}).inside);
    // A pentagram drawn in one stroke: its middle is crossed twice, so even-odd says outside.
    const Polygon star{{{50.f, 0.f}, {79.f, 90.f}, {2.f, 35.f}, {98.f, 35.f}, {21.f, 90.f}}};
    EXPECT_FALSE(pointInPolygon(star, {50.f, 50.f}).inside);
    EXPECT_TRUE(pointInPolygon(star, {50.f, 20.f}).inside); // the top point
}

TEST(PointInPolygon, ZeroAreaAndTooFewCornersAreNeverInside)
{
    EXPECT_FALSE(pointInPolygon(Polygon{}, {0.f, 0.f}).inside);
    EXPECT_FALSE(pointInPolygon(Polygon{{{3.f, 3.f}}}, {3.f, 3.f}).inside);
    EXPECT_TRUE(pointInPolygon(Polygon{{{3.f, 3.f}}}, {3.f, 3.f}).onEdge);
    const Polygon flat{{{0.f, 0.f}, {10.f, 0.f}, {20.f, 0.f}}};
    EXPECT_FALSE(pointInPolygon(flat, {5.f, 0.f}).inside);
    EXPECT_TRUE(pointInPolygon(flat, {5.f, 0.f}).onEdge);
    EXPECT_FALSE(pointInPolygon(flat, {5.f, 1.f}).inside);
    const Polygon slanted{{{0.f, 0.f}, {10.f, 10.f}, {20.f, 20.f}}};
    EXPECT_FALSE(pointInPolygon(slanted, {5.f, 6.f}).inside);
    EXPECT_FALSE(pointInPolygon(slanted, {-5.f, 5.f}).inside);
}

TEST(PointInPolygon, RepeatedCornersAreIgnored)
{
    const Polygon doubled{
        {{0.f, 0.f}, {0.f, 0.f}, {10.f, 0.f}, {10.f, 10.f}, {10.f, 10.f}, {0.f, 10.f}}};
    EXPECT_TRUE(pointInPolygon(doubled, {5.f, 5.f}).inside);
    EXPECT_FALSE(pointInPolygon(doubled, {15.f, 5.f}).inside);
    EXPECT_TRUE(pointInPolygon(doubled, {10.f, 10.f}).onEdge);
}

TEST(PointInPolygon, NegativeCoordinatesWorkAsAnyOther)
{
    const Polygon shifted{{{-20.f, -20.f}, {-10.f, -20.f}, {-10.f, -10.f}, {-20.f, -10.f}}};
    EXPECT_TRUE(pointInPolygon(shifted, {-15.f, -15.f}).inside);
    EXPECT_FALSE(pointInPolygon(shifted, {-5.f, -15.f}).inside);
    EXPECT_TRUE(pointInPolygon(shifted, {-20.f, -15.f}).onEdge);
}

TEST(PointInPolygon, NaNAndInfinityAreNeverInside)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const Vec2 point : {Vec2{nan, 5.f}, Vec2{5.f, nan}, Vec2{-inf, 5.f}})
    {
        const PointInPolygonResult result = pointInPolygon(square, point);
        EXPECT_FALSE(result.inside);
        EXPECT_FALSE(result.onEdge);
        EXPECT_EQ(result.crossings, 0);
    }
    Polygon broken = square;
    broken.points[2] = {nan, 10.f};
    EXPECT_FALSE(pointInPolygon(broken, {5.f, 5.f}).inside);
    EXPECT_FALSE(pointInPolygon(broken, {10.f, 10.f}).onEdge);
}

TEST(PointInPolygon, HugeIsExactInsideTheRangeAndNeverInsideBeyondIt)
{
    // Near the edge of the range (1e6 px), one pixel from a slanted edge still counts.
    const Polygon far{{{999000.f, 999000.f}, {1000000.f, 999000.f}, {999000.f, 1000000.f}}};
    EXPECT_TRUE(pointInPolygon(far, {999499.f, 999500.f}).inside);
    EXPECT_TRUE(pointInPolygon(far, {999500.f, 999500.f}).onEdge);
    EXPECT_FALSE(pointInPolygon(far, {999501.f, 999500.f}).inside);
    // Beyond it: no answer but "not inside".
    const Polygon tooFar{{{-2e6f, -2e6f}, {2e6f, -2e6f}, {2e6f, 2e6f}, {-2e6f, 2e6f}}};
    EXPECT_FALSE(pointInPolygon(tooFar, {0.f, 0.f}).inside);
    EXPECT_FALSE(pointInPolygon(square, {2e6f, 5.f}).inside);
}
