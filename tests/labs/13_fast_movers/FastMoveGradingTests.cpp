// Grading tests of lab 13 (fast movers). Each suite is named after the task it checks;
// README.md lists them. A bullet 8 pixels wide flies at a wall 6 pixels thick, at speeds
// from 600 to 10 million pixels per second, one fixed step (1/120 s) at a time; every
// flight ends within a few steps, so no test loops long. Sub-steps are counted by the given
// WallTests (Given.cpp, always the course's copy), which remembers where each test ran.
#include "labs/13_fast_movers/FastMoveChecks.h"

#include "FastMove.h"
#include "RangeLevel.h"

#include "hitbox/app/Loop.h"
#include "hitbox/debug/DebugRenderer.h"

#include "hitbox/geometry/Shapes.h"

#include <gtest/gtest.h>

namespace
{
using namespace fastmovechecks;

constexpr float dt = hitbox::stepSeconds; // the programs' fixed step (Loop.h)
constexpr float maxSubStep = 8.f;       // less than wall (6) + bullet (8): no sub-step can jump it
const Box wall{500.f, 0.f, 6.f, 100.f}; // right side 506, bottom 100

Box bulletAt(float left, float top = 48.f)
{
    return {left, top, 8.f, 4.f};
}

Step subStepped()
{
    return subSteppingAgainst(wall, dt, maxSubStep);
}

Step speculative()
{
    return speculatingAgainst(wall, dt);
}
} // namespace

TEST(Task1SubSteps, NeverPassesThroughTheWallAtAnySpeed)
{
    for (float speed = 600.f; speed < 2e5f; speed *= 1.7f)
        for (float start = 380.f; start < 420.f; start += 7.f)
        {
            expectStopsAtTheWall(wall, subStepped(), bulletAt(start), speed, 40);
            expectStopsAtTheWall(wall, subStepped(), bulletAt(1000.f - start), -speed, 40);
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
    EXPECT_TRUE(testedAlongTheMove(tests, 0.f, 100.f, maxSubStep, 13, true));
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
    EXPECT_TRUE(testedAlongTheMove(tests, start, 100.f, maxSubStep, 3, false))
        << "sub-steps 1 and 2 are free, the 3rd hits: then stop";
}

TEST(Task1SubSteps, AShortStepIsOneSubStep)
{
    // 5 px, shorter than maxSubStep: one move, one overlap test, as a discrete step.
    WallTests tests(wall);
    const MoveResult result = subSteppedStep(bulletAt(0.f, 200.f), 600.f, dt, tests, maxSubStep);
    EXPECT_NEAR(result.bullet.left, 5.f, 1e-4f);
    EXPECT_TRUE(testedAlongTheMove(tests, 0.f, 5.f, maxSubStep, 1, true));
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
            expectStopsAtTheWall(wall, speculative(), bulletAt(start), speed, 40);
            expectStopsAtTheWall(wall, speculative(), bulletAt(1000.f - start), -speed, 40);
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
