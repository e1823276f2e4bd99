// TunnellingTest.cpp - when a discrete test can miss (Tunnelling.h).
#include "hitbox/geometry/Tunnelling.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Sweep.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

using hitbox::canTunnel;

namespace
{
const hitbox::Box paper(500.f, 0.f, 1.f, 100.f);
const hitbox::Box bullet(400.f, 48.f, 4.f, 4.f);
const float notANumber = std::numeric_limits<float>::quiet_NaN();

// The miss itself: the sweep says the mover hits the target during the step, but the
// discrete test sees no overlap at the start nor at the end of it.
bool discreteTestMisses(const hitbox::Box& mover, hitbox::Vec2 step, const hitbox::Box& target)
{
    const hitbox::Box end(mover.left + step.x, mover.top + step.y, mover.width, mover.height);
    return hitbox::sweepBoxVsBox(mover, step, target).hit && !hitbox::boxVsBox(mover, target) &&
           !hitbox::boxVsBox(end, target);
}
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

TEST(CanTunnel, NaNNeverTunnels)
{
    EXPECT_FALSE(canTunnel(bullet, {notANumber, 0.f}, paper));
    EXPECT_FALSE(canTunnel(bullet, {120.f, 0.f}, {500.f, notANumber, 1.f, 100.f}));
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
        if (discreteTestMisses(mover, step, target))
        {
            ++misses;
            ASSERT_TRUE(canTunnel(mover, step, target))
                << ::testing::PrintToString(mover) << " " << ::testing::PrintToString(step) << " "
                << ::testing::PrintToString(target);
        }
    }
    EXPECT_GT(misses, 100);
}
