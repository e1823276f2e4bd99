// SlopeTest.cpp - a slope tile (Slope.h): the ground's height, and a box's foot standing on
// it; one test per edge of the rules.
#include "hitbox/geometry/Slope.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <limits>

using hitbox::Box;
using hitbox::Slope;
using hitbox::SlopeFoot;
using hitbox::SlopeGround;
using hitbox::slopeGroundAt;
using hitbox::standOnSlope;

namespace
{
// A 45-degree tile 48 px wide rising to the right: from (96, 240) up to (144, 192). y down.
const Slope rising{{96.f, 240.f}, {144.f, 192.f}};
const float snap = 12.f;

// A 32 x 60 box whose foot (middle of its bottom) is at (x, y).
Box boxWithFootAt(float x, float y)
{
    return {x - 16.f, y - 60.f, 32.f, 60.f};
}
} // namespace

TEST(SlopeGround, IsOnTheStraightLineBetweenTheEnds)
{
    const SlopeGround middle = slopeGroundAt(rising, 120.f);
    ASSERT_TRUE(middle.over);
    EXPECT_FLOAT_EQ(middle.y, 216.f);
    EXPECT_FLOAT_EQ(slopeGroundAt(rising, 108.f).y, 228.f);
    // A falling slope, and a shallow one (two tiles wide, one tile high).
    EXPECT_FLOAT_EQ(slopeGroundAt({{0.f, 0.f}, {48.f, 48.f}}, 12.f).y, 12.f);
    EXPECT_FLOAT_EQ(slopeGroundAt({{0.f, 48.f}, {96.f, 0.f}}, 24.f).y, 36.f);
}

TEST(SlopeGround, TheEndsAreOnTheSlopeAndBesideThemIsNot)
{
    EXPECT_TRUE(slopeGroundAt(rising, 96.f).over);
    EXPECT_FLOAT_EQ(slopeGroundAt(rising, 96.f).y, 240.f);
    EXPECT_TRUE(slopeGroundAt(rising, 144.f).over);
    EXPECT_FLOAT_EQ(slopeGroundAt(rising, 144.f).y, 192.f);
    EXPECT_FALSE(slopeGroundAt(rising, 95.99f).over);
    EXPECT_FALSE(slopeGroundAt(rising, 144.01f).over);
}

TEST(SlopeGround, EndsGivenRightToLeftAreTheSameSlope)
{
    const Slope backwards{rising.right, rising.left};
    EXPECT_TRUE(slopeGroundAt(backwards, 120.f).over);
    EXPECT_FLOAT_EQ(slopeGroundAt(backwards, 120.f).y, 216.f);
    EXPECT_FALSE(slopeGroundAt(backwards, 150.f).over);
}

TEST(SlopeGround, AVerticalOrZeroWidthSlopeIsAWallNotGround)
{
    EXPECT_FALSE(slopeGroundAt({{96.f, 240.f}, {96.f, 192.f}}, 96.f).over);
    EXPECT_FALSE(slopeGroundAt({{96.f, 240.f}, {96.f, 240.f}}, 96.f).over);
}

TEST(SlopeGround, NaNInfinityAndOutOfRangeAreNotOver)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(slopeGroundAt(rising, nan).over);
    EXPECT_FALSE(slopeGroundAt({{nan, 240.f}, {144.f, 192.f}}, 120.f).over);
    EXPECT_FALSE(slopeGroundAt({{96.f, 240.f}, {inf, 192.f}}, 120.f).over);
    EXPECT_FALSE(slopeGroundAt({{-2e6f, 240.f}, {144.f, 192.f}}, 120.f).over);
}

TEST(SlopeFoot, AFootBelowTheSurfaceIsPushedUpOntoIt)
{
    // Walking up: the foot ended 5 px inside the slope at x = 120 (surface 216).
    const SlopeFoot foot = standOnSlope(boxWithFootAt(120.f, 221.f), 27.5f, rising, snap);
    ASSERT_TRUE(foot.grounded);
    EXPECT_FLOAT_EQ(foot.moveY, -5.f);
}

TEST(SlopeFoot, AFootAboveTheSurfaceWithinTheSnapIsPulledDownOntoIt)
{
    // Walking down: the ground fell away 3.5 px under the foot in one step; it follows it.
    const SlopeFoot foot = standOnSlope(boxWithFootAt(120.f, 212.5f), 0.f, rising, snap);
    ASSERT_TRUE(foot.grounded);
    EXPECT_FLOAT_EQ(foot.moveY, 3.5f);
    // Exactly the snap distance above still snaps; further is in the air.
    EXPECT_TRUE(standOnSlope(boxWithFootAt(120.f, 204.f), 0.f, rising, snap).grounded);
    const SlopeFoot high = standOnSlope(boxWithFootAt(120.f, 203.9f), 0.f, rising, snap);
    EXPECT_FALSE(high.grounded);
    EXPECT_FLOAT_EQ(high.moveY, 0.f);
}

TEST(SlopeFoot, AFootExactlyOnTheSurfaceStandsWithoutMoving)
{
    const SlopeFoot foot = standOnSlope(boxWithFootAt(120.f, 216.f), 0.f, rising, 0.f);
    EXPECT_TRUE(foot.grounded);
    EXPECT_FLOAT_EQ(foot.moveY, 0.f);
}

TEST(SlopeFoot, ARisingBoxIsNeverSnappedDownNorPushedUp)
{
    // A jump from the slope: 6 px above it after the first step, well within the snap, and
    // still going up: it must leave the slope. Rising from inside it is not pushed either.
    for (const float footY : {210.f, 216.f, 221.f})
    {
        const SlopeFoot foot = standOnSlope(boxWithFootAt(120.f, footY), -1112.f, rising, snap);
        EXPECT_FALSE(foot.grounded) << "foot at y " << footY;
        EXPECT_FLOAT_EQ(foot.moveY, 0.f);
    }
    // Velocity 0 (the top of a jump, or standing) is not rising.
    EXPECT_TRUE(standOnSlope(boxWithFootAt(120.f, 214.f), 0.f, rising, snap).grounded);
}

TEST(SlopeFoot, OnlyTheFootCountsNotTheCorners)
{
    // The box's right half hangs over the slope's end, its foot is over the slope: it stands.
    EXPECT_TRUE(standOnSlope(boxWithFootAt(140.f, 196.f), 0.f, rising, snap).grounded);
    // The foot is beside the slope, though the box's right half is over it: nothing.
    const SlopeFoot beside = standOnSlope(boxWithFootAt(90.f, 250.f), 0.f, rising, snap);
    EXPECT_FALSE(beside.grounded);
    EXPECT_FLOAT_EQ(beside.moveY, 0.f);
    // The foot exactly at the slope's ends counts.
    EXPECT_FLOAT_EQ(standOnSlope(boxWithFootAt(96.f, 238.f), 0.f, rising, snap).moveY, 2.f);
    EXPECT_FLOAT_EQ(standOnSlope(boxWithFootAt(144.f, 194.f), 0.f, rising, snap).moveY, -2.f);
}

TEST(SlopeFoot, AFootDeeperThanTheSlopesLowestEndIsUnderItNotOnIt)
{
    // The lowest end is at y 240: a foot at x 120 and y 240 is inside the slope (lifted 24 px
    // onto the surface); at 241 it is below the slope tile, in the tile under it: not lifted.
    EXPECT_TRUE(standOnSlope(boxWithFootAt(120.f, 240.f), 0.f, rising, snap).grounded);
    EXPECT_FALSE(standOnSlope(boxWithFootAt(120.f, 241.f), 0.f, rising, snap).grounded);
}

TEST(SlopeFoot, NoSnapDistanceOnlyCatchesAFootOnOrBelowTheSurface)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const float none : {0.f, -5.f, nan})
    {
        EXPECT_FALSE(standOnSlope(boxWithFootAt(120.f, 215.f), 0.f, rising, none).grounded);
        EXPECT_TRUE(standOnSlope(boxWithFootAt(120.f, 217.f), 0.f, rising, none).grounded);
    }
}

TEST(SlopeFoot, NegativeSizesAreReadNormalised)
{
    // The same box as boxWithFootAt(120, 221), given from its bottom-right corner.
    const Box backwards{136.f, 221.f, -32.f, -60.f};
    const SlopeFoot foot = standOnSlope(backwards, 0.f, rising, snap);
    ASSERT_TRUE(foot.grounded);
    EXPECT_FLOAT_EQ(foot.moveY, -5.f);
}

TEST(SlopeFoot, NaNInfinityAndOutOfRangeDoNothing)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const Box inside = boxWithFootAt(120.f, 221.f);
    EXPECT_FALSE(standOnSlope(inside, nan, rising, snap).grounded);
    EXPECT_FALSE(standOnSlope(inside, inf, rising, snap).grounded);
    EXPECT_FALSE(standOnSlope({nan, 161.f, 32.f, 60.f}, 0.f, rising, snap).grounded);
    EXPECT_FALSE(standOnSlope({104.f, 161.f, 32.f, 3e6f}, 0.f, rising, snap).grounded);
    EXPECT_FALSE(standOnSlope(inside, 0.f, {{nan, 240.f}, {144.f, 192.f}}, snap).grounded);
}
