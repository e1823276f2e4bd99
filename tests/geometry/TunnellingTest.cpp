// TunnellingTest.cpp - when a discrete test can miss, swept bounds, speculative contacts
// (Tunnelling.h).
#include "hitbox/geometry/Tunnelling.h"
#include "hitbox/geometry/Overlap.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

using hitbox::canTunnel;
using hitbox::Circle;

namespace
{
const hitbox::Box paper(500.f, 0.f, 1.f, 100.f);
const hitbox::Box bullet(400.f, 48.f, 4.f, 4.f);
const float dt = 1.f / 120.f;
const float notANumber = std::numeric_limits<float>::quiet_NaN();
} // namespace

TEST(CanTunnel, AStepLongerThanBothWidthsCanJumpTheWall)
{
    EXPECT_TRUE(canTunnel(bullet, {120.f, 0.f}, paper)); // 120 px a step
    EXPECT_TRUE(canTunnel(bullet, {5.f, 0.f},
                          {404.f, 0.f, 1.f, 100.f})); // exactly 4 + 1: touching to touching
    EXPECT_FALSE(canTunnel(bullet, {4.9f, 0.f}, {404.f, 0.f, 1.f, 100.f}));
}

TEST(CanTunnel, ASlowStepCannot)
{
    EXPECT_FALSE(canTunnel(bullet, {3.f, 0.f}, {404.f, 0.f, 1.f, 100.f}));
}

TEST(CanTunnel, AWallOutsideTheSweptBoundsCannotBeTunnelled)
{
    EXPECT_FALSE(canTunnel(bullet, {120.f, 0.f}, {500.f, 200.f, 1.f, 100.f})); // below the path
    EXPECT_FALSE(canTunnel(bullet, {-120.f, 0.f}, paper));                     // going away
}

TEST(CanTunnel, CirclesCompareTheStepWithBothDiameters)
{
    const Circle ball{{0.f, 0.f}, 5.f};
    const Circle target{{50.f, 0.f}, 5.f};
    EXPECT_TRUE(canTunnel(ball, {100.f, 0.f}, target));
    EXPECT_FALSE(canTunnel(ball, {19.f, 0.f}, Circle{{10.f, 0.f}, 5.f}));
    EXPECT_FALSE(
        canTunnel(ball, {100.f, 0.f}, Circle{{50.f, 10.f}, 5.f})); // passes beside, touching
    EXPECT_TRUE(canTunnel(ball, {120.f, 0.f}, paper) == false);    // box far away
    EXPECT_TRUE(canTunnel(Circle{{400.f, 50.f}, 2.f}, {120.f, 0.f}, paper));
}

TEST(CanTunnel, NaNOrNegativeRadiusNeverTunnels)
{
    EXPECT_FALSE(canTunnel(bullet, {notANumber, 0.f}, paper));
    EXPECT_FALSE(canTunnel(Circle{{400.f, 50.f}, -2.f}, {120.f, 0.f}, paper));
    EXPECT_FALSE(canTunnel(Circle{{0.f, 0.f}, 5.f}, {100.f, 0.f}, Circle{{50.f, 0.f}, notANumber}));
}

TEST(CanTunnel, WarnsBeforeEveryStraightMissOfADiscreteTest)
{
    // Axis-aligned moves: whenever the discrete test really misses a crossing, canTunnel
    // said it could happen; when it says it cannot, the discrete test never misses.
    std::mt19937 random(9u);
    std::uniform_real_distribution<float> place(0.f, 200.f);
    std::uniform_real_distribution<float> size(0.5f, 30.f);
    std::uniform_real_distribution<float> move(-100.f, 100.f);
    int misses = 0;
    for (int i = 0; i < 50000; ++i)
    {
        const hitbox::Box mover(place(random), place(random), size(random), size(random));
        const hitbox::Box target(place(random), place(random), size(random), size(random));
        const hitbox::Vec2 step =
            i % 2 ? hitbox::Vec2(move(random), 0.f) : hitbox::Vec2(0.f, move(random));
        if (hitbox::discreteTestMisses(mover, step, target))
        {
            ++misses;
            ASSERT_TRUE(canTunnel(mover, step, target))
                << ::testing::PrintToString(mover) << " " << ::testing::PrintToString(step) << " "
                << ::testing::PrintToString(target);
        }
    }
    EXPECT_GT(misses, 100);
}

TEST(DiscreteTestMisses, TheBulletThroughPaper)
{
    const hitbox::Vec2 step = hitbox::Vec2(1.0e4f, 0.f) * dt; // 83 px a step
    hitbox::Box atTheStart(450.f, 48.f, 4.f, 4.f);
    EXPECT_TRUE(hitbox::discreteTestMisses(atTheStart, step, paper));
    // Slow enough and the discrete test sees it at the end of some step.
    EXPECT_FALSE(hitbox::discreteTestMisses({497.f, 48.f, 4.f, 4.f}, {2.f, 0.f}, paper));
    EXPECT_TRUE(hitbox::discreteTestMisses(Circle{{0.f, 0.f}, 1.f}, {100.f, 0.f},
                                           Circle{{50.f, 0.f}, 1.f}));
    EXPECT_FALSE(
        hitbox::discreteTestMisses(Circle{{0.f, 0.f}, 1.f}, {49.f, 0.f}, Circle{{50.f, 0.f}, 1.f}));
}

TEST(SweptBounds, HoldsTheStartAndTheEnd)
{
    const hitbox::Box bounds = hitbox::sweptBounds(bullet, {-100.f, 30.f});
    EXPECT_EQ(bounds, hitbox::Box(300.f, 48.f, 104.f, 34.f));
    EXPECT_EQ(hitbox::sweptBounds(bullet, {0.f, 0.f}), bullet);
    EXPECT_EQ(hitbox::sweptBounds(hitbox::Box(404.f, 52.f, -4.f, -4.f), {0.f, 0.f}), bullet);
    EXPECT_EQ(hitbox::sweptBounds(Circle{{10.f, 10.f}, 5.f}, {20.f, 0.f}),
              hitbox::Box(5.f, 5.f, 30.f, 10.f));
}

TEST(SpeculativeVelocity, ShortensTheMoveToEndTouching)
{
    const hitbox::Vec2 velocity(2.0e4f, 0.f); // 167 px a step: would pass the wall
    const hitbox::Vec2 clamped = hitbox::speculativeVelocity(bullet, velocity, dt, {paper});
    EXPECT_NEAR(bullet.left + bullet.width + clamped.x * dt, 500.f, 1e-3f);
    EXPECT_EQ(clamped.y, 0.f);
}

TEST(SpeculativeVelocity, TheNearestSolidDecides)
{
    const std::vector<hitbox::Box> solids{paper, {450.f, 0.f, 1.f, 100.f}};
    const hitbox::Vec2 clamped = hitbox::speculativeVelocity(bullet, {1.0e4f, 0.f}, dt, solids);
    EXPECT_NEAR(bullet.left + bullet.width + clamped.x * dt, 450.f, 1e-3f);
}

TEST(SpeculativeVelocity, NoHitOrStartingInsideKeepsTheVelocity)
{
    EXPECT_EQ(hitbox::speculativeVelocity(bullet, {-1.0e4f, 0.f}, dt, {paper}),
              hitbox::Vec2(-1.0e4f, 0.f));
    EXPECT_EQ(hitbox::speculativeVelocity({499.f, 48.f, 4.f, 4.f}, {1.0e4f, 0.f}, dt, {paper}),
              hitbox::Vec2(1.0e4f, 0.f));
    EXPECT_EQ(hitbox::speculativeVelocity(bullet, {1.0e4f, 0.f}, 0.f, {paper}),
              hitbox::Vec2(1.0e4f, 0.f));
}

TEST(SpeculativeVelocity, NeverEndsInsideTheWallSoNoLaterStepPassesThrough)
{
    // Moving to the exact time of impact can round to a hair inside the wall; a box that
    // starts inside keeps its full velocity, so that would let it pass straight through.
    std::mt19937 random(2024);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    const float frame = 1.f / 60.f;
    int endedInside = 0;
    int passedThrough = 0;
    for (int sample = 0; sample < 20000; ++sample)
    {
        hitbox::Box mover(100.f * unit(random), 100.f * unit(random), 1.f + 19.f * unit(random),
                          1.f + 19.f * unit(random));
        // Tall enough that no path can go round it: passing it means passing through it.
        const hitbox::Box wall(150.f + 150.f * unit(random), -300.f, 1.f + 19.f * unit(random),
                               700.f);
        const hitbox::Vec2 velocity(100.f + 19900.f * unit(random), 4000.f * unit(random) - 2000.f);
        for (int step = 0; step < 3; ++step)
        {
            const hitbox::Vec2 kept = hitbox::speculativeVelocity(mover, velocity, frame, {wall});
            mover.left += kept.x * frame;
            mover.top += kept.y * frame;
            endedInside += hitbox::boxVsBox(mover, wall);
        }
        passedThrough += mover.left >= wall.left + wall.width;
    }
    EXPECT_EQ(endedInside, 0);
    EXPECT_EQ(passedThrough, 0);
}
