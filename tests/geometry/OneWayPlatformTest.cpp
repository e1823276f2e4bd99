// OneWayPlatformTest.cpp - a one-way platform (OneWayPlatform.h): one test per edge of its rule.
#include "hitbox/geometry/OneWayPlatform.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <limits>

using hitbox::Box;
using hitbox::oneWayPlatformStop;
using hitbox::OneWayStop;
using hitbox::Vec2;

namespace
{
const Box platform{100.f, 200.f, 96.f, 16.f}; // top edge at y = 200, from x = 100 to 196
const Box player{130.f, 168.f, 16.f, 32.f};   // 16 x 32; its bottom is 200 at top 168

// The player moved so that its bottom starts at `bottom`.
Box playerWithBottom(float bottom)
{
    Box body = player;
    body.top = bottom - body.height;
    return body;
}
} // namespace

TEST(OneWayPlatform, AFallingBodyLandsOnTheTop)
{
    // Bottom at 190, falling 20: it would end 10 px into the platform; it lands after 10.
    const OneWayStop stop = oneWayPlatformStop(playerWithBottom(190.f), {3.f, 20.f}, platform);
    ASSERT_TRUE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 10.f);
    EXPECT_FLOAT_EQ(stop.move.x, 3.f); // sideways motion is the caller's, untouched
}

TEST(OneWayPlatform, StandingOnItWithGravityStaysOnIt)
{
    // Bottom exactly on the top (touching counts as above) and gravity pulls 0.5 px this step:
    // held, with no vertical move at all.
    const OneWayStop stop = oneWayPlatformStop(playerWithBottom(200.f), {2.f, 0.5f}, platform);
    ASSERT_TRUE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 0.f);
    EXPECT_FLOAT_EQ(stop.move.x, 2.f);
}

TEST(OneWayPlatform, ZeroVelocityIsNeverBlocked)
{
    // Standing still on it, or resting inside it: nothing to stop, the move is unchanged.
    for (const float bottom : {200.f, 205.f, 150.f})
    {
        const OneWayStop stop = oneWayPlatformStop(playerWithBottom(bottom), {0.f, 0.f}, platform);
        EXPECT_FALSE(stop.blocked) << "bottom " << bottom;
        EXPECT_FLOAT_EQ(stop.move.y, 0.f);
    }
}

TEST(OneWayPlatform, MovingUpPassesThrough)
{
    // Jumping from below, from inside it, and from on top: upward moves are never cut.
    for (const float bottom : {230.f, 210.f, 200.f})
    {
        const OneWayStop stop =
            oneWayPlatformStop(playerWithBottom(bottom), {0.f, -40.f}, platform);
        EXPECT_FALSE(stop.blocked) << "bottom " << bottom;
        EXPECT_FLOAT_EQ(stop.move.y, -40.f);
    }
}

TEST(OneWayPlatform, ABodyThatStartedBelowTheTopFallsThrough)
{
    // Half-way up through it when the jump peaked: the bottom (201) is already below the top,
    // so falling back is not a landing (no snap up onto the platform).
    const OneWayStop stop = oneWayPlatformStop(playerWithBottom(201.f), {0.f, 5.f}, platform);
    EXPECT_FALSE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 5.f);
}

TEST(OneWayPlatform, EndingExactlyOnTheTopIsNotABlock)
{
    // Touching is not colliding: a step that ends with the bottom on the top needs no cut ...
    const OneWayStop exact = oneWayPlatformStop(playerWithBottom(190.f), {0.f, 10.f}, platform);
    EXPECT_FALSE(exact.blocked);
    EXPECT_FLOAT_EQ(exact.move.y, 10.f);
    // ... one that stops above it neither; one a hair further down is cut to the top.
    EXPECT_FALSE(oneWayPlatformStop(playerWithBottom(180.f), {0.f, 10.f}, platform).blocked);
    const OneWayStop past = oneWayPlatformStop(playerWithBottom(190.f), {0.f, 10.25f}, platform);
    EXPECT_TRUE(past.blocked);
    EXPECT_FLOAT_EQ(past.move.y, 10.f);
}

TEST(OneWayPlatform, OnlyABodyOverThePlatformLands)
{
    // The platform spans x 100..196. A 16-wide body at x 84 only touches its left end: it
    // falls past; at x 85 it overlaps by 1 px and lands. The same at the right end (x 196).
    EXPECT_FALSE(oneWayPlatformStop({84.f, 160.f, 16.f, 32.f}, {0.f, 20.f}, platform).blocked);
    EXPECT_TRUE(oneWayPlatformStop({85.f, 160.f, 16.f, 32.f}, {0.f, 20.f}, platform).blocked);
    EXPECT_FALSE(oneWayPlatformStop({196.f, 160.f, 16.f, 32.f}, {0.f, 20.f}, platform).blocked);
    EXPECT_TRUE(oneWayPlatformStop({195.f, 160.f, 16.f, 32.f}, {0.f, 20.f}, platform).blocked);
}

TEST(OneWayPlatform, TheSideIsJudgedWhenTheBottomReachesTheTop)
{
    // Bottom 190, falling 20 while moving 40 right: it reaches the top half-way (t = 0.5,
    // 20 px right). Starting at x 64 it is at 84..100 then (touching the end): falls past,
    // although it ends over the platform. Starting at x 200, moving 40 left: at 180..196 then,
    // over the platform: lands, although it started beside it.
    EXPECT_FALSE(oneWayPlatformStop({64.f, 158.f, 16.f, 32.f}, {40.f, 20.f}, platform).blocked);
    EXPECT_TRUE(oneWayPlatformStop({200.f, 158.f, 16.f, 32.f}, {-40.f, 20.f}, platform).blocked);
}

TEST(OneWayPlatform, NegativeSizesAreReadNormalised)
{
    // The player box drawn from its bottom-right corner: the same box, the same landing.
    const OneWayStop stop = oneWayPlatformStop({146.f, 190.f, -16.f, -32.f}, {0.f, 20.f}, platform);
    ASSERT_TRUE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 10.f);
}

TEST(OneWayPlatform, BadNumbersNeverBlock)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(oneWayPlatformStop(playerWithBottom(190.f), {0.f, nan}, platform).blocked);
    EXPECT_FALSE(oneWayPlatformStop(playerWithBottom(190.f), {0.f, inf}, platform).blocked);
    EXPECT_FALSE(oneWayPlatformStop({nan, 158.f, 16.f, 32.f}, {0.f, 20.f}, platform).blocked);
    EXPECT_FALSE(oneWayPlatformStop(playerWithBottom(190.f), {0.f, 20.f}, {100.f, 2e6f, 96.f, 16.f})
                     .blocked);
}

TEST(OneWayPlatform, FarFromTheOriginASixteenthOfAPixelStillCounts)
{
    // At y = 1e6 a float step is 1/16 px: a fall that ends one step below the top is a landing.
    const Box far{0.f, 1e6f, 96.f, 16.f};
    const Box body{10.f, 1e6f - 40.f, 16.f, 32.f}; // bottom 8 px above the top
    EXPECT_TRUE(oneWayPlatformStop(body, {0.f, 8.0625f}, far).blocked);
    EXPECT_FALSE(oneWayPlatformStop(body, {0.f, 8.f}, far).blocked);
}
