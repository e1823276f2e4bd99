// Hidden variants of lab 13's grading tests: the same behaviour as FastMoveGradingTests.cpp
// with another wall, another bullet, other speeds, step lengths and directions. The
// instructor's build and the class grader run them; the student handout leaves
// tests/labs-hidden/ out, so no one can tune an answer to them. As in the visible tests, the
// given WallTests (Given.cpp) counts the overlap tests and remembers where each one ran.
#include "labs/13_fast_movers/FastMoveChecks.h"

#include "FastMove.h"

#include "hitbox/geometry/Shapes.h"

#include <gtest/gtest.h>

namespace
{
using namespace fastmovechecks;

// A thinner, shorter wall left of zero, and a smaller bullet than the visible tests use.
const Box thinWall{-300.f, -20.f, 3.f, 40.f}; // right side -297, bottom 20
constexpr float bulletWidth = 5.f;
constexpr float bulletHeight = 2.f;
constexpr float limit = 7.f; // sub-steps: less than wall (3) + bullet (5), so none jumps it
constexpr float slowDt = 1.f / 90.f;

Box bulletAt(float left, float top = -3.f)
{
    return {left, top, bulletWidth, bulletHeight};
}

// Flies the bullet at the thin wall from `gap` pixels left of it and from `gap` pixels right.
void expectStopsFromEitherSide(const Step& step, float speed, float gap)
{
    expectStopsAtTheWall(thinWall, step, bulletAt(thinWall.left - bulletWidth - gap), speed, 40);
    expectStopsAtTheWall(thinWall, step, bulletAt(hitbox::rightOf(thinWall) + gap), -speed, 40);
}
} // namespace

TEST(Task1SubSteps, HiddenNeverPassesAThinWallAtOtherSpeedsAndStepLengths)
{
    // A 3-pixel wall, a 5-pixel bullet, sub-steps of at most 7 and a longer step (1/90 s).
    const Step subStepped = subSteppingAgainst(thinWall, slowDt, limit);
    for (float speed = 450.f; speed < 2e5f; speed *= 1.9f)
        for (float gap = 11.f; gap < 150.f; gap += 26.f)
            expectStopsFromEitherSide(subStepped, speed, gap);
}

TEST(Task1SubSteps, HiddenALeftwardStepIsCutIntoEnoughSubSteps)
{
    // 90 px to the left in one step of 1/60 s, passing below the wall: ceil(90 / 4) = 23
    // sub-steps, each tested, the last at the end. A count tuned to the visible 100 px / 8 px
    // (13) or a move always to the right fails.
    WallTests tests(thinWall);
    const float start = 40.f;
    const MoveResult result =
        subSteppedStep(bulletAt(start, 100.f), -5400.f, 1.f / 60.f, tests, 4.f);
    EXPECT_FALSE(result.hitWall);
    EXPECT_NEAR(result.bullet.left, start - 90.f, 1e-3f);
    EXPECT_TRUE(testedAlongTheMove(tests, start, -90.f, 4.f, 23, true));
}

TEST(Task1SubSteps, HiddenAMoveOfWholeSubStepsNeedsNoExtraOne)
{
    // Exactly 96 px with sub-steps of at most 8 (every number exact in binary): 12 sub-steps,
    // not 13. Rounding up a whole number of sub-steps once more is one test too many.
    WallTests tests(thinWall);
    const MoveResult result = subSteppedStep(bulletAt(-200.f, 60.f), 384.f, 0.25f, tests, 8.f);
    EXPECT_FALSE(result.hitWall);
    EXPECT_EQ(result.bullet.left, -104.f);
    EXPECT_TRUE(testedAlongTheMove(tests, -200.f, 96.f, 8.f, 12, true));
}

TEST(Task1SubSteps, HiddenStopsTestingAtTheFirstHitComingFromTheRight)
{
    // 100 px to the left in sub-steps of 100/15 (or 7) px, starting 30 px right of the wall:
    // the 5th sub-step enters it. Then the step is over, the bullet against the right side.
    WallTests tests(thinWall);
    const float start = hitbox::rightOf(thinWall) + 30.f;
    const MoveResult result = subSteppedStep(bulletAt(start), -9000.f, slowDt, tests, limit);
    EXPECT_TRUE(result.hitWall);
    EXPECT_EQ(result.bullet.left, hitbox::rightOf(thinWall));
    EXPECT_TRUE(testedAlongTheMove(tests, start, -100.f, limit, 5, false))
        << "sub-steps 1 to 4 are free, the 5th hits: then stop";
}

TEST(Task1SubSteps, HiddenTouchingTheThinWallIsNotAHit)
{
    // Against its right side moving right (away): free, the whole move. Against it moving
    // left (in): a hit at once, and it stays. Skimming along its top edge: never a hit.
    WallTests awayTests(thinWall);
    const MoveResult away =
        subSteppedStep(bulletAt(hitbox::rightOf(thinWall)), 900.f, slowDt, awayTests, limit);
    EXPECT_FALSE(away.hitWall);
    EXPECT_NEAR(away.bullet.left, hitbox::rightOf(thinWall) + 10.f, 1e-3f);
    WallTests intoTests(thinWall);
    const MoveResult into =
        subSteppedStep(bulletAt(hitbox::rightOf(thinWall)), -900.f, slowDt, intoTests, limit);
    EXPECT_TRUE(into.hitWall);
    EXPECT_EQ(into.bullet.left, hitbox::rightOf(thinWall));
    WallTests skimTests(thinWall);
    const Box skimming = bulletAt(thinWall.left - 20.f, thinWall.top - bulletHeight);
    const MoveResult skim = subSteppedStep(skimming, 2700.f, slowDt, skimTests, limit);
    EXPECT_FALSE(skim.hitWall) << "the bullet's bottom on the wall's top edge only touches it";
    EXPECT_NEAR(skim.bullet.left, skimming.left + 30.f, 1e-3f);
}

TEST(Task2SpeculativeContact, HiddenNeverOverlapsAThinWallAtOtherSpeeds)
{
    const Step speculative = speculatingAgainst(thinWall, slowDt);
    for (float speed = 450.f; speed < 2e7f; speed *= 2.3f)
        for (float gap = 3.f; gap < 160.f; gap += 31.f)
            expectStopsFromEitherSide(speculative, speed, gap);
}

TEST(Task2SpeculativeContact, HiddenComingFromTheRightTheWholeMoveOrTheGap)
{
    // Moving left: 30 px short of a 40 px gap is taken whole; 60 px ends against the right
    // side; a move exactly as long as the gap ends there too (hit or not, the place is the
    // same).
    const float start = hitbox::rightOf(thinWall) + 40.f;
    const MoveResult shortMove = speculativeStep(bulletAt(start), -2700.f, slowDt, thinWall);
    EXPECT_FALSE(shortMove.hitWall);
    EXPECT_NEAR(shortMove.bullet.left, start - 30.f, 1e-3f);
    const MoveResult longMove = speculativeStep(bulletAt(start), -5400.f, slowDt, thinWall);
    EXPECT_TRUE(longMove.hitWall);
    EXPECT_EQ(longMove.bullet.left, hitbox::rightOf(thinWall));
    const MoveResult exact = speculativeStep(bulletAt(start), -160.f, 0.25f, thinWall);
    EXPECT_EQ(exact.bullet.left, hitbox::rightOf(thinWall));
}

TEST(Task2SpeculativeContact, HiddenLevelMeansTheYRangesOverlapStrictly)
{
    // A bullet taller than the wall (covering it top to bottom) and one dipping a quarter
    // pixel over its top are level with it and stop; one whose top is exactly on the wall's
    // bottom only touches it and flies on.
    const float left = hitbox::rightOf(thinWall) + 20.f;
    const Box tall{left, thinWall.top - 10.f, bulletWidth, thinWall.height + 20.f};
    const MoveResult covering = speculativeStep(tall, -1e6f, slowDt, thinWall);
    EXPECT_TRUE(covering.hitWall) << "a bullet taller than the wall is level with it";
    EXPECT_EQ(covering.bullet.left, hitbox::rightOf(thinWall));
    const MoveResult dipping = speculativeStep(bulletAt(left, thinWall.top - bulletHeight + 0.25f),
                                               -1e6f, slowDt, thinWall);
    EXPECT_TRUE(dipping.hitWall) << "a quarter pixel over the top edge is level";
    EXPECT_EQ(dipping.bullet.left, hitbox::rightOf(thinWall));
    const MoveResult under =
        speculativeStep(bulletAt(left, hitbox::bottomOf(thinWall)), -1e6f, slowDt, thinWall);
    EXPECT_FALSE(under.hitWall) << "touching the bottom edge is not level";
    EXPECT_LT(hitbox::rightOf(under.bullet), thinWall.left);
}

TEST(Task2SpeculativeContact, HiddenAWallBehindTheBulletNeverStopsIt)
{
    // Left of the wall and moving left, or right of it and moving right, at any speed: the
    // whole move, no hit, also when it starts touching the wall.
    for (const float speed : {450.f, 9000.f, 3e6f})
    {
        const Box leftOfIt = bulletAt(thinWall.left - bulletWidth);
        const MoveResult left = speculativeStep(leftOfIt, -speed, slowDt, thinWall);
        EXPECT_FALSE(left.hitWall) << "at " << speed;
        EXPECT_NEAR(left.bullet.left, leftOfIt.left - speed * slowDt, 1e-3f * speed);
        const Box rightOfIt = bulletAt(hitbox::rightOf(thinWall) + 12.f);
        const MoveResult right = speculativeStep(rightOfIt, speed, slowDt, thinWall);
        EXPECT_FALSE(right.hitWall) << "at " << speed;
        EXPECT_NEAR(right.bullet.left, rightOfIt.left + speed * slowDt, 1e-3f * speed);
    }
}
