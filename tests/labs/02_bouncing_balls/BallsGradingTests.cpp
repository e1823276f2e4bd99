// Grading tests of lab 2 (bouncing balls). Each suite is named after the task it checks;
// README.md lists them. The level runs with no window, one fixed step at a time.
#include "labs/LabTesting.h"

#include "Ball.h"
#include "BallsLevel.h"

#include "hitbox/App.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{

// How far two balls may overlap at the end of a step. The response separates them in the
// step they meet, so only rounding is left.
constexpr float overlapTolerance = 0.5f;

float dot(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.x + a.y * b.y;
}

float length(sf::Vector2f v)
{
    return std::sqrt(dot(v, v));
}

float overlapOf(const Ball& a, const Ball& b)
{
    return a.getRadius() + b.getRadius() - length(a.getPosition() - b.getPosition());
}

void run(BallsLevel& level, float seconds)
{
    hitbox::simulate(level, static_cast<long long>(seconds * hitbox::stepsPerSecond));
}

// A level with only the balls a test puts in it.
BallsLevel emptyLevel()
{
    BallsLevel level;
    level.removeAllBalls();
    return level;
}

const sf::Vector2f middle{600.f, 337.5f};

} // namespace

TEST(Level, StartsWithTwoBallsFlyingAtEachOther)
{
    BallsLevel level;
    ASSERT_EQ(level.getBallCount(), 2);
    EXPECT_GT(level.getBall(0).getVelocity().x, 0.f);
    EXPECT_LT(level.getBall(1).getVelocity().x, 0.f);
    EXPECT_FLOAT_EQ(level.getBall(0).getVelocity().x, ballSpeed);
}

TEST(Task1BounceOffTheWalls, BallNeverLeavesTheWindow)
{
    BallsLevel level = emptyLevel();
    level.addBall(middle, {ballSpeed * 1.3f, ballSpeed * 0.9f});
    const sf::Vector2f world = level.getWorldSize();
    for (int step = 0; step < 20 * 120; ++step)
    {
        hitbox::simulate(level, 1);
        const Ball& ball = level.getBall(0);
        const sf::Vector2f center = ball.getPosition();
        const float r = ball.getRadius();
        ASSERT_TRUE(center.x >= r - 0.01f && center.x <= world.x - r + 0.01f &&
                    center.y >= r - 0.01f && center.y <= world.y - r + 0.01f)
            << "after step " << step << " the ball at " << labtesting::text(center)
            << " sticks out of the " << world.x << " x " << world.y << " window";
    }
}

TEST(Task1BounceOffTheWalls, BallComesBackFromEachWallAtTheSameSpeed)
{
    const sf::Vector2f directions[] = {{1.f, 0.f}, {-1.f, 0.f}, {0.f, 1.f}, {0.f, -1.f}};
    for (sf::Vector2f direction : directions)
    {
        BallsLevel level = emptyLevel();
        level.addBall(middle, direction * ballSpeed);
        // Long enough to reach the wall it flies at, not the one across from it.
        const sf::Vector2f toWall =
            level.getWorldSize() / 2.f - sf::Vector2f(ballRadius, ballRadius);
        run(level, std::abs(dot(toWall, direction)) / ballSpeed + 0.5f);
        const sf::Vector2f velocity = level.getBall(0).getVelocity();
        EXPECT_VEC_NEAR(velocity, -direction * ballSpeed, 0.01f)
            << "a ball sent towards " << labtesting::text(direction)
            << " should come back the way it went";
    }
}

TEST(Task1BounceOffTheWalls, BallMovingAlongAWallKeepsMovingAlongIt)
{
    // Only the velocity across the wall changes: the part along it stays.
    BallsLevel level = emptyLevel();
    level.addBall({600.f, 40.f}, {ballSpeed, -ballSpeed});
    run(level, 0.5f);
    EXPECT_FLOAT_EQ(level.getBall(0).getVelocity().x, ballSpeed);
    EXPECT_FLOAT_EQ(level.getBall(0).getVelocity().y, ballSpeed);
}

TEST(Task2TestEachPairWithTheBoundingCircle, OverlappingBallsAreBothToldAboutTheHit)
{
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{40.f, 10.f}, {});
    hitbox::simulate(level, 1);
    EXPECT_EQ(level.getBall(0).getHitCount(), 1);
    EXPECT_EQ(level.getBall(1).getHitCount(), 1);
}

TEST(Task2TestEachPairWithTheBoundingCircle, BallsOnlyTouchingAreNotAHit)
{
    // Touching is not colliding (the framework's edge rule): centres exactly 2r apart.
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{2.f * ballRadius, 0.f}, {});
    hitbox::simulate(level, 1);
    EXPECT_EQ(level.getBall(0).getHitCount(), 0);
    EXPECT_EQ(level.getBall(1).getHitCount(), 0);
}

TEST(Task2TestEachPairWithTheBoundingCircle, DiagonalNeighboursWhoseBoxesOverlapAreNotAHit)
{
    // Their boxes overlap at the corners but the circles do not: a circle test, not a box test.
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{1.6f * ballRadius, 1.6f * ballRadius}, {});
    hitbox::simulate(level, 1);
    EXPECT_EQ(level.getBall(0).getHitCount(), 0);
}

TEST(Task2TestEachPairWithTheBoundingCircle, EveryPairIsTested)
{
    // Three balls in a row, each overlapping the next: 0-1 and 1-2 hit, 0-2 does not.
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{50.f, 0.f}, {});
    level.addBall(middle + sf::Vector2f{100.f, 0.f}, {});
    level.addBall(middle + sf::Vector2f{-100.f, 200.f}, {}); // alone
    hitbox::simulate(level, 1);
    EXPECT_EQ(level.getBall(0).getHitCount(), 1);
    EXPECT_EQ(level.getBall(1).getHitCount(), 2);
    EXPECT_EQ(level.getBall(2).getHitCount(), 1);
    EXPECT_EQ(level.getBall(3).getHitCount(), 0);
}

TEST(Task3BounceApartLikeBilliardBalls, HeadOnBallsReverseAfterContactAndNeverOverlap)
{
    BallsLevel level; // the lecture's example: two balls on one line, flying at each other
    float worstOverlap = 0.f;
    bool met = false;
    for (int step = 0; step < 2 * 120; ++step)
    {
        hitbox::simulate(level, 1);
        const float overlap = overlapOf(level.getBall(0), level.getBall(1));
        worstOverlap = std::max(worstOverlap, overlap);
        met = met || overlap > -1.f;
    }
    ASSERT_TRUE(met) << "the balls should meet within two seconds";
    EXPECT_LE(worstOverlap, overlapTolerance) << "after a step the balls may not overlap";
    EXPECT_FLOAT_EQ(level.getBall(0).getVelocity().x, -ballSpeed) << "the left ball goes back left";
    EXPECT_FLOAT_EQ(level.getBall(1).getVelocity().x, ballSpeed)
        << "the right ball goes back right";
}

TEST(Task3BounceApartLikeBilliardBalls, MovingBallHittingABallAtRestStopsAndPassesItsSpeedOn)
{
    // Equal masses, elastic, head-on: the velocities are exchanged (Newton's cradle).
    BallsLevel level = emptyLevel();
    level.addBall(middle - sf::Vector2f{200.f, 0.f}, {ballSpeed, 0.f});
    level.addBall(middle, {});
    run(level, 1.f);
    EXPECT_VEC_NEAR(level.getBall(0).getVelocity(), sf::Vector2f(0.f, 0.f), 0.01f);
    EXPECT_VEC_NEAR(level.getBall(1).getVelocity(), sf::Vector2f(ballSpeed, 0.f), 0.01f);
}

TEST(Task3BounceApartLikeBilliardBalls, GlancingHitKeepsMomentumAndEnergy)
{
    BallsLevel level = emptyLevel();
    const sf::Vector2f startA{ballSpeed, 0.f};
    const sf::Vector2f startB{-0.5f * ballSpeed, 0.2f * ballSpeed};
    level.addBall(middle - sf::Vector2f{150.f, 20.f}, startA);
    level.addBall(middle + sf::Vector2f{0.f, 10.f}, startB);
    run(level, 0.6f); // they meet after about 0.35 s, before any wall
    const sf::Vector2f a = level.getBall(0).getVelocity();
    const sf::Vector2f b = level.getBall(1).getVelocity();
    ASSERT_GT(level.getBall(0).getHitCount(), 0) << "the balls should have met";
    EXPECT_VEC_NEAR(a + b, startA + startB, 0.05f) << "total momentum is kept";
    EXPECT_NEAR(dot(a, a) + dot(b, b), dot(startA, startA) + dot(startB, startB), 1.f)
        << "total kinetic energy is kept (an elastic collision)";
    EXPECT_GT(length(a - startA), 10.f) << "the hit should change the velocities";
}

TEST(Task3BounceApartLikeBilliardBalls, OverlappingBallsArePushedApartUntilTheyTouch)
{
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{30.f, 0.f}, {});
    hitbox::simulate(level, 1);
    EXPECT_NEAR(overlapOf(level.getBall(0), level.getBall(1)), 0.f, overlapTolerance);
    EXPECT_NEAR(level.getBall(0).getPosition().x + level.getBall(1).getPosition().x,
                2.f * middle.x + 30.f, 0.01f)
        << "each ball moves half the overlap, so their midpoint stays put";
}

TEST(Task3BounceApartLikeBilliardBalls, BallsAlreadyMovingApartAreNotPulledBack)
{
    // Overlapping but separating (e.g. pushed together by a wall): no sticking together.
    BallsLevel level = emptyLevel();
    level.addBall(middle, {-ballSpeed, 0.f});
    level.addBall(middle + sf::Vector2f{40.f, 0.f}, {ballSpeed, 0.f});
    hitbox::simulate(level, 1);
    EXPECT_FLOAT_EQ(level.getBall(0).getVelocity().x, -ballSpeed);
    EXPECT_FLOAT_EQ(level.getBall(1).getVelocity().x, ballSpeed);
}

TEST(Task3BounceApartLikeBilliardBalls, ManyBallsStayInsideAndApart)
{
    BallsLevel level(20, 7);
    ASSERT_EQ(level.getBallCount(), 20);
    const sf::Vector2f world = level.getWorldSize();
    // In a crowd a ball pushed out of one ball can be pushed into another in the same
    // step; allow what two balls close in one step.
    const float crowdTolerance = 2.f * ballSpeed * hitbox::stepSeconds + overlapTolerance;
    for (int step = 0; step < 10 * 120; ++step)
    {
        hitbox::simulate(level, 1);
        for (int i = 0; i < level.getBallCount(); ++i)
        {
            const sf::Vector2f c = level.getBall(i).getPosition();
            // (A ball pushed by another can end a step slightly past a wall; its own
            // update puts it back in the next step.)
            const float low = ballRadius - crowdTolerance;
            ASSERT_TRUE(c.x >= low && c.x <= world.x - low && c.y >= low && c.y <= world.y - low)
                << "ball " << i << " left the window at step " << step;
            for (int j = i + 1; j < level.getBallCount(); ++j)
                ASSERT_LE(overlapOf(level.getBall(i), level.getBall(j)), crowdTolerance)
                    << "balls " << i << " and " << j << " at step " << step;
        }
    }
}
