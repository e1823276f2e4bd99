// RayCircleTest.cpp - a segment against a circle (RayCircle.h): one test per edge rule.
#include "hitbox/geometry/RayCircle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using hitbox::Circle;
using hitbox::RayCircleResult;
using hitbox::segmentVsCircle;
using hitbox::Vec2;

namespace
{
const Circle unit10{{0.f, 0.f}, 10.f}; // radius 10 about the origin
}

TEST(RayCircle, AHeadOnRayEntersAndLeaves)
{
    // From x = -20 to x = 20 through the middle: enters at x = -10 (t = 0.25), leaves at
    // x = 10 (t = 0.75).
    const RayCircleResult result = segmentVsCircle({-20.f, 0.f}, {20.f, 0.f}, unit10);
    ASSERT_TRUE(result.hit);
    EXPECT_FALSE(result.startedInside);
    EXPECT_FLOAT_EQ(result.nearTime, 0.25f);
    EXPECT_FLOAT_EQ(result.farTime, 0.75f);
    EXPECT_FLOAT_EQ(result.point.x, -10.f);
    EXPECT_FLOAT_EQ(result.point.y, 0.f);
    EXPECT_FLOAT_EQ(result.normal.x, -1.f);
    EXPECT_FLOAT_EQ(result.normal.y, 0.f);
}

TEST(RayCircle, AnOffCentreRayEntersOnASlant)
{
    // y = 6: the chord runs from x = -8 to x = 8 (a 6-8-10 triangle).
    const RayCircleResult result = segmentVsCircle({-18.f, 6.f}, {22.f, 6.f}, unit10);
    ASSERT_TRUE(result.hit);
    EXPECT_FLOAT_EQ(result.nearTime, 0.25f);
    EXPECT_FLOAT_EQ(result.farTime, 0.65f);
    EXPECT_FLOAT_EQ(result.normal.x, -0.8f);
    EXPECT_FLOAT_EQ(result.normal.y, 0.6f);
}

TEST(RayCircle, AMissIsNoHit)
{
    const RayCircleResult result = segmentVsCircle({-20.f, 11.f}, {20.f, 11.f}, unit10);
    EXPECT_FALSE(result.hit);
    EXPECT_FLOAT_EQ(result.normal.x, 0.f);
    EXPECT_FALSE(segmentVsCircle({20.f, 0.f}, {40.f, 0.f}, unit10).hit);   // heading away
    EXPECT_FALSE(segmentVsCircle({-40.f, 0.f}, {-20.f, 0.f}, unit10).hit); // stops short
}

// Edge rule: touching is not colliding.
TEST(RayCircle, AGrazingRayIsNoHit)
{
    EXPECT_FALSE(segmentVsCircle({-20.f, 10.f}, {20.f, 10.f}, unit10).hit);
    EXPECT_FALSE(segmentVsCircle({-20.f, -10.f}, {20.f, -10.f}, unit10).hit);
    EXPECT_TRUE(segmentVsCircle({-20.f, 9.9f}, {20.f, 9.9f}, unit10).hit);
}

TEST(RayCircle, ReachingTheRimOnlyAtTheEndIsNoHit)
{
    EXPECT_FALSE(segmentVsCircle({-20.f, 0.f}, {-10.f, 0.f}, unit10).hit);
    const RayCircleResult justIn = segmentVsCircle({-20.f, 0.f}, {-9.f, 0.f}, unit10);
    ASSERT_TRUE(justIn.hit);
    EXPECT_NEAR(justIn.nearTime, 10.f / 11.f, 1e-6f);
    EXPECT_GT(justIn.farTime, 1.f); // it leaves beyond the segment's end
}

TEST(RayCircle, StartingOnTheRimHitsOnlyHeadingIn)
{
    const RayCircleResult in = segmentVsCircle({-10.f, 0.f}, {10.f, 0.f}, unit10);
    ASSERT_TRUE(in.hit);
    EXPECT_FALSE(in.startedInside);
    EXPECT_FLOAT_EQ(in.nearTime, 0.f);
    EXPECT_FLOAT_EQ(in.farTime, 1.f);
    EXPECT_FALSE(segmentVsCircle({-10.f, 0.f}, {-20.f, 0.f}, unit10).hit); // heading out
    EXPECT_FALSE(segmentVsCircle({-10.f, 0.f}, {-10.f, 5.f}, unit10).hit); // along the tangent
}

TEST(RayCircle, StartingInsideHitsAtTimeZero)
{
    const RayCircleResult result = segmentVsCircle({0.f, 0.f}, {20.f, 0.f}, unit10);
    ASSERT_TRUE(result.hit);
    EXPECT_TRUE(result.startedInside);
    EXPECT_FLOAT_EQ(result.nearTime, 0.f);
    EXPECT_FLOAT_EQ(result.farTime, 0.5f);
    EXPECT_FLOAT_EQ(result.point.x, 0.f);
    EXPECT_FLOAT_EQ(result.normal.x, 0.f);
    EXPECT_FLOAT_EQ(result.normal.y, 0.f);
}

TEST(RayCircle, AZeroLengthSegmentHitsOnlyStrictlyInside)
{
    EXPECT_TRUE(segmentVsCircle({3.f, 4.f}, {3.f, 4.f}, unit10).startedInside);
    EXPECT_FALSE(segmentVsCircle({6.f, 8.f}, {6.f, 8.f}, unit10).hit); // on the rim
    EXPECT_FALSE(segmentVsCircle({20.f, 0.f}, {20.f, 0.f}, unit10).hit);
}

TEST(RayCircle, ZeroAndNegativeRadiiAreNeverHit)
{
    EXPECT_FALSE(segmentVsCircle({-20.f, 0.f}, {20.f, 0.f}, Circle{{0.f, 0.f}, 0.f}).hit);
    EXPECT_FALSE(segmentVsCircle({-20.f, 0.f}, {20.f, 0.f}, Circle{{0.f, 0.f}, -10.f}).hit);
    EXPECT_FALSE(segmentVsCircle({0.f, 0.f}, {0.f, 0.f}, Circle{{0.f, 0.f}, -10.f}).hit);
}

TEST(RayCircle, NegativeCoordinatesWorkLikeAnyOther)
{
    const Circle left{{-100.f, -50.f}, 10.f};
    const RayCircleResult result = segmentVsCircle({-100.f, -100.f}, {-100.f, 0.f}, left);
    ASSERT_TRUE(result.hit);
    EXPECT_FLOAT_EQ(result.nearTime, 0.4f);
    EXPECT_FLOAT_EQ(result.normal.y, -1.f);
}

TEST(RayCircle, NaNAndInfinityAreNoHit)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(segmentVsCircle({nan, 0.f}, {20.f, 0.f}, unit10).hit);
    EXPECT_FALSE(segmentVsCircle({-20.f, 0.f}, {inf, 0.f}, unit10).hit);
    EXPECT_FALSE(segmentVsCircle({-20.f, 0.f}, {20.f, 0.f}, Circle{{0.f, nan}, 10.f}).hit);
    EXPECT_FALSE(segmentVsCircle({-20.f, 0.f}, {20.f, 0.f}, Circle{{0.f, 0.f}, nan}).hit);
    EXPECT_FALSE(segmentVsCircle({0.f, 0.f}, {20.f, 0.f}, Circle{{0.f, 0.f}, inf}).hit);
}

TEST(RayCircle, HugeIsExactInsideTheRangeAndNoHitBeyondIt)
{
    // A 1 px circle near the edge of the range, crossed by a ray 1e6 px long.
    const Circle far{{999000.f, 0.f}, 1.f};
    const RayCircleResult result = segmentVsCircle({-1000000.f, 0.f}, {1000000.f, 0.f}, far);
    ASSERT_TRUE(result.hit);
    EXPECT_NEAR(result.point.x, 998999.f, 0.0625f);
    EXPECT_FLOAT_EQ(result.normal.x, -1.f);
    EXPECT_FALSE(segmentVsCircle({-1000000.f, 1.f}, {1000000.f, 1.f}, far).hit); // grazes
    EXPECT_FALSE(segmentVsCircle({-2e6f, 0.f}, {2e6f, 0.f}, unit10).hit);        // beyond
}
