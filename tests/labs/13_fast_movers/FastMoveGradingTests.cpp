// Grading tests of lab 13 (fast movers). Each suite is named after the task it checks;
// README.md lists them. A bullet 8 pixels wide flies at a wall 6 pixels thick, at speeds
// from 600 to 10 million pixels per second, one fixed step (1/120 s) at a time; every
// flight ends within a few steps, so no test loops long. Sub-steps are counted by the given
// WallTests (Given.cpp, always the course's copy), which remembers where each test ran.
#include "FastMove.h"
#include "RangeLevel.h"

#include "hitbox/app/Loop.h"
#include "hitbox/debug/DebugRenderer.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>

namespace
{
constexpr float dt = hitbox::stepSeconds; // the programs' fixed step (Loop.h)
constexpr float maxSubStep = 8.f;       // less than wall (6) + bullet (8): no sub-step can jump it
const Box wall{500.f, 0.f, 6.f, 100.f}; // right side 506, bottom 100

Box bulletAt(float left, float top = 48.f)
{
    return {left, top, 8.f, 4.f};
}

using Step = std::function<MoveResult(const Box&, float)>;

// Flies the bullet from `start` at `velocityX` for up to `steps` steps; expects it to stop
// against the wall's near side, never overlapping it after a step and never past it.
void expectStopsAtTheWall(const Step& step, Box start, float velocityX, int steps)
{
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

Step subStepped()
{
    return [](const Box& bullet, float velocityX)
    {
        WallTests tests(wall);
        return subSteppedStep(bullet, velocityX, dt, tests, maxSubStep);
    };
}

// Where the overlap tests of one step ran, for a step from `left` that moves `move` pixels:
// `count` tests, the bullet moving the same way before each, never more than maxSubStep
// pixels (equal sub-steps, as the sheet says, or maxSubStep each and the rest last: both
// cure tunnelling); with `whole`, the last test ran at the end of the move.
testing::AssertionResult testedAlongTheMove(const WallTests& tests, float left, float move,
                                            int count, bool whole)
{
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

Step speculative()
{
    return [](const Box& bullet, float velocityX)
    { return speculativeStep(bullet, velocityX, dt, wall); };
}
} // namespace

TEST(Task1SubSteps, NeverPassesThroughTheWallAtAnySpeed)
{
    for (float speed = 600.f; speed < 2e5f; speed *= 1.7f)
        for (float start = 380.f; start < 420.f; start += 7.f)
        {
            expectStopsAtTheWall(subStepped(), bulletAt(start), speed, 40);
            expectStopsAtTheWall(subStepped(), bulletAt(1000.f - start), -speed, 40);
        }
}

TEST(Task1SubSteps, EachSubStepIsNoLongerThanTheLimit)
{
    // 100 pixels in one step, no wall in the way: ceil(100 / 8) = 13 sub-steps.
    WallTests tests(wall);
    const MoveResult result = subSteppedStep(bulletAt(0.f, 200.f), 12000.f, dt, tests, maxSubStep);
    EXPECT_FALSE(result.hitWall);
    EXPECT_NEAR(result.bullet.left, 100.f, 1e-3f)
        << "a step without a hit still moves the whole way";
    EXPECT_TRUE(testedAlongTheMove(tests, 0.f, 100.f, 13, true));
}

TEST(Task1SubSteps, StopsTestingAtTheFirstHit)
{
    // 100 pixels in 13 sub-steps of 100/13 px, the bullet's right side 20 px before the
    // wall: the third sub-step reaches it. After that hit the step is over: no more moves,
    // no more overlap tests (the count is what the level shows as the step's cost).
    WallTests tests(wall);
    const float start = wall.left - 8.f - 20.f;
    const MoveResult result = subSteppedStep(bulletAt(start), 12000.f, dt, tests, maxSubStep);
    EXPECT_TRUE(result.hitWall);
    EXPECT_EQ(hitbox::rightOf(result.bullet), wall.left);
    EXPECT_TRUE(testedAlongTheMove(tests, start, 100.f, 3, false))
        << "sub-steps 1 and 2 are free, the 3rd hits: then stop";
}

TEST(Task1SubSteps, AShortStepIsOneSubStep)
{
    // 5 px, shorter than maxSubStep: one move, one overlap test, as a discrete step.
    WallTests tests(wall);
    const MoveResult result = subSteppedStep(bulletAt(0.f, 200.f), 600.f, dt, tests, maxSubStep);
    EXPECT_NEAR(result.bullet.left, 5.f, 1e-4f);
    EXPECT_TRUE(testedAlongTheMove(tests, 0.f, 5.f, 1, true));
}

TEST(Task1SubSteps, TouchingTheWallIsNotAHit)
{
    // Against the wall and moving away: free. Against it and moving in: it stays there.
    const MoveResult away = subStepped()(bulletAt(wall.left - 8.f), -600.f);
    EXPECT_FALSE(away.hitWall);
    EXPECT_LT(hitbox::rightOf(away.bullet), wall.left);
    const MoveResult into = subStepped()(bulletAt(wall.left - 8.f), 600.f);
    EXPECT_TRUE(into.hitWall);
    EXPECT_EQ(hitbox::rightOf(into.bullet), wall.left);
}

TEST(Task2SpeculativeContact, NeverOverlapsTheWallAtAnySpeed)
{
    for (float speed = 600.f; speed < 1e7f; speed *= 1.7f)
        for (float start = 300.f; start < 480.f; start += 23.f)
        {
            expectStopsAtTheWall(speculative(), bulletAt(start), speed, 40);
            expectStopsAtTheWall(speculative(), bulletAt(1000.f - start), -speed, 40);
        }
}

TEST(Task2SpeculativeContact, TheWholeMoveWhenTheWallIsFarAndTouchingWhenNot)
{
    const MoveResult far = speculativeStep(bulletAt(100.f), 1200.f, dt, wall);
    EXPECT_FALSE(far.hitWall);
    EXPECT_NEAR(far.bullet.left, 110.f, 1e-3f);
    const MoveResult fast = speculativeStep(bulletAt(100.f), 1e7f, dt, wall);
    EXPECT_TRUE(fast.hitWall);
    EXPECT_EQ(hitbox::rightOf(fast.bullet), wall.left) << "a move past the wall ends touching it";
}

TEST(Task2SpeculativeContact, OnlyAWallLevelWithTheBulletStopsIt)
{
    // Flying below the wall (the bullet's top exactly at the wall's bottom: touching).
    const MoveResult below =
        speculativeStep(bulletAt(100.f, hitbox::bottomOf(wall)), 1e6f, dt, wall);
    EXPECT_FALSE(below.hitWall);
    EXPECT_GT(below.bullet.left, hitbox::rightOf(wall));
    // Moving away from a wall it touches.
    const MoveResult away = speculativeStep(bulletAt(hitbox::rightOf(wall)), 600.f, dt, wall);
    EXPECT_FALSE(away.hitWall);
    EXPECT_NEAR(away.bullet.left, hitbox::rightOf(wall) + 5.f, 1e-3f);
}

TEST(Task2SpeculativeContact, TheEdgesOfTheRule)
{
    // Touching the wall's side and moving in: it stays there, a hit (both sides).
    MoveResult in = speculativeStep(bulletAt(wall.left - 8.f), 600.f, dt, wall);
    EXPECT_TRUE(in.hitWall);
    EXPECT_EQ(hitbox::rightOf(in.bullet), wall.left);
    in = speculativeStep(bulletAt(hitbox::rightOf(wall)), -600.f, dt, wall);
    EXPECT_TRUE(in.hitWall);
    EXPECT_EQ(in.bullet.left, hitbox::rightOf(wall));
    // At rest against either side: touching is not a hit, and nothing moves.
    for (const float left : {wall.left - 8.f, hitbox::rightOf(wall)})
    {
        const MoveResult still = speculativeStep(bulletAt(left), 0.f, dt, wall);
        EXPECT_FALSE(still.hitWall) << "a bullet at rest touching the wall at left " << left;
        EXPECT_EQ(still.bullet.left, left);
    }
    // A tiny move (0.5 px) from 0.25 px away, from either side: it ends against the wall.
    const MoveResult tinyRight = speculativeStep(bulletAt(wall.left - 8.25f), 60.f, dt, wall);
    EXPECT_EQ(hitbox::rightOf(tinyRight.bullet), wall.left);
    const MoveResult tinyLeft =
        speculativeStep(bulletAt(hitbox::rightOf(wall) + 0.25f), -60.f, dt, wall);
    EXPECT_EQ(tinyLeft.bullet.left, hitbox::rightOf(wall));
    // Sliding past just above the wall (the bullet's bottom on the wall's top edge): no wall.
    const Box above{wall.left - 20.f, wall.top - 4.f, 8.f, 4.f};
    const MoveResult past = speculativeStep(above, 6000.f, dt, wall);
    EXPECT_FALSE(past.hitWall) << "touching the wall's top edge is not level with it";
    EXPECT_NEAR(past.bullet.left, above.left + 50.f, 1e-3f);
}

// The level's own rules (no task): given code, so they pass on the starter too.
TEST(Level, ShotsSpeedUpToTheStatedTopSpeedAndStayThere)
{
    // Before: after 1e6 px/s the speed silently went back to 600 px/s.
    float speed = RangeLevel::firstSpeed;
    for (int shot = 0; shot < 100; ++shot)
    {
        const float next = RangeLevel::nextShotSpeed(speed);
        EXPECT_GE(next, speed) << "shot " << shot;
        EXPECT_LE(next, RangeLevel::topSpeed) << "shot " << shot;
        speed = next;
    }
    EXPECT_EQ(speed, RangeLevel::topSpeed);
}

TEST(DebugView, ShowsEachLanesBulletAndNextMove)
{
    // Before: the help line offered F1 but the lab drew nothing with it.
    RangeLevel level;
    hitbox::DebugRenderer debug;
    level.renderDebug(debug);
    EXPECT_GT(debug.getVertices().getVertexCount(), 100u);
}
