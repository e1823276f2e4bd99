// FastMoveChecks.h - lab 13's checks on a bullet's flight: that it stops against a wall and
// never tunnels, and where a sub-stepped step ran its overlap tests. Both the grading tests
// (FastMoveGradingTests.cpp) and their hidden variants (tests/labs-hidden/13_fast_movers/) use it.
#pragma once

#include "FastMove.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace fastmovechecks
{

// One step of an answer under test: the bullet's box and velocity along x in, the result out.
using Step = std::function<MoveResult(const Box&, float)>;

// Task 1's cure as the tests fly it: fresh WallTests each step, so each step's tests are its own.
inline Step subSteppingAgainst(const Box& wall, float dt, float maxSubStep)
{
    return [=](const Box& bullet, float velocityX)
    {
        WallTests tests(wall);
        return subSteppedStep(bullet, velocityX, dt, tests, maxSubStep);
    };
}

// Task 2's cure as the tests fly it, so its flights are checked exactly like task 1's.
inline Step speculatingAgainst(const Box& wall, float dt)
{
    return [=](const Box& bullet, float velocityX)
    { return speculativeStep(bullet, velocityX, dt, wall); };
}

// A cure for tunnelling must stop the bullet at the wall at every speed, never in or past it.
inline void expectStopsAtTheWall(const Box& wall, const Step& step, Box start, float velocityX,
                                 int steps)
{
    // Flies the bullet from `start` for up to `steps` steps: never overlapping the wall after a
    // step, never past it, and ending exactly against its near side.
    Box bullet = start;
    for (int index = 0; index < steps; ++index)
    {
        const MoveResult result = step(bullet, velocityX);
        bullet = result.bullet;
        ASSERT_FALSE(hitbox::boxVsBox(bullet, wall))
            << "the bullet overlaps the wall after a step at " << velocityX << " px/s: left "
            << bullet.left;
        if (result.hitWall)
        {
            if (velocityX > 0.f)
                EXPECT_EQ(hitbox::rightOf(bullet), wall.left)
                    << "stopped, but not against the wall's left side";
            else
                EXPECT_EQ(bullet.left, hitbox::rightOf(wall))
                    << "stopped, but not against the wall's right side";
            return;
        }
        const bool past = velocityX > 0.f ? bullet.left >= hitbox::rightOf(wall)
                                          : hitbox::rightOf(bullet) <= wall.left;
        ASSERT_FALSE(past) << "the bullet went through the wall at " << velocityX
                           << " px/s (started at left " << start.left << "), now at left "
                           << bullet.left;
    }
    ADD_FAILURE() << "the bullet never reached the wall at " << velocityX << " px/s";
}

// Sub-stepping cures tunnelling only if every sub-step is short and followed by its own test.
inline testing::AssertionResult testedAlongTheMove(const WallTests& tests, float left, float move,
                                                   float maxSubStep, int count, bool whole)
{
    // Where the overlap tests of one step ran, for a step from `left` that moves `move` pixels:
    // `count` tests, the bullet moving the same way before each, never more than maxSubStep
    // pixels (equal sub-steps, as the sheet says, or maxSubStep each and the rest last: both
    // cure tunnelling); with `whole`, the last test ran at the end of the move.
    const std::vector<Box>& tested = tests.tested();
    if (static_cast<int>(tested.size()) != count)
        return testing::AssertionFailure()
               << tested.size() << " overlap tests ran; expected " << count
               << " (a test after each sub-step of at most " << maxSubStep << " px)";
    float previous = left;
    for (std::size_t index = 0; index < tested.size(); ++index)
    {
        const float step = (tested[index].left - previous) * (move < 0.f ? -1.f : 1.f);
        if (!(step > 0.f && step <= maxSubStep + 1e-3f))
            return testing::AssertionFailure()
                   << "overlap test " << index + 1 << " ran with the bullet's left side at "
                   << tested[index].left << ", " << step << " px on from the one before (at "
                   << previous << "): each sub-step moves it on, by at most " << maxSubStep;
        previous = tested[index].left;
    }
    if (whole && std::abs(previous - (left + move)) > 1e-3f)
        return testing::AssertionFailure()
               << "the last overlap test ran at left " << previous
               << ", not at the end of the move (" << left + move << ")";
    return testing::AssertionSuccess();
}

} // namespace fastmovechecks
