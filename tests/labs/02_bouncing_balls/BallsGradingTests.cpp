// Grading tests of lab 2 (bouncing balls). Each suite is named after the task it checks;
// README.md lists them. The level runs with no window, one fixed step at a time.
#include "labs/LabTesting.h"

#include "Ball.h"
#include "BallsLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

// The tests do not use the numbers at the top of Ball.h (students are invited to change
// them): each test sets up its own balls at its own speed, and places them by the radius
// the balls have, so every test checks the same thing whatever ballSpeed and ballRadius are.
namespace
{

// How far two balls may overlap at the end of a step. The response separates them in the
// step they meet, so only rounding is left.
constexpr float overlapTolerance = 0.5f;
// The speed the tests give their balls (pixels per second): slow enough that a test
// decides when a ball reaches a wall.
constexpr float testSpeed = 260.f;

float overlapOf(const Ball& a, const Ball& b)
{
    return a.getRadius() + b.getRadius() -
           hitbox::length(hitbox::toVec2(a.getPosition() - b.getPosition()));
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

// The radius every ball has (ballRadius, whatever it is set to).
float radius()
{
    return Ball({}, {}, sf::Color::White).getRadius();
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
    level.addBall(middle, {testSpeed * 1.3f, testSpeed * 0.9f});
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
        level.addBall(middle, direction * testSpeed);
        // Long enough to reach the wall it flies at, not the one across from it.
        const sf::Vector2f toWall = level.getWorldSize() / 2.f - sf::Vector2f(radius(), radius());
        run(level,
            std::abs(hitbox::dot(hitbox::toVec2(toWall), hitbox::toVec2(direction))) / testSpeed +
                0.5f);
        const sf::Vector2f velocity = level.getBall(0).getVelocity();
        EXPECT_VEC_NEAR(velocity, -direction * testSpeed, 0.01f)
            << "a ball sent towards " << labtesting::text(direction)
            << " should come back the way it went";
    }
}

TEST(Task1BounceOffTheWalls, BallHittingAWallAtAnAngleKeepsItsSpeedAlongTheWall)
{
    // Only the velocity across the wall changes: the part along it stays.
    BallsLevel level = emptyLevel();
    level.addBall({600.f, radius() + 40.f}, {testSpeed, -testSpeed}); // up and right
    run(level, 0.5f); // it reaches the top wall after about 0.15 s
    const sf::Vector2f velocity = level.getBall(0).getVelocity();
    EXPECT_FLOAT_EQ(velocity.x, testSpeed)
        << "a ball flying up and to the right into the top wall should keep its speed to the "
           "right (along the wall): only the up-down part of the velocity changes";
    EXPECT_FLOAT_EQ(velocity.y, testSpeed)
        << "a ball flying up into the top wall should come away downwards at the same speed";
}

TEST(Task1BounceOffTheWalls, BallSlidingAlongAWallIsNotHittingIt)
{
    // The edge rule: touching is not colliding. A ball exactly touching the top wall (and
    // one touching the left wall), moving along it, never hits it: with <= instead of <
    // it would "hit" every step and flash all the time.
    const float r = radius();
    const sf::Vector2f world = emptyLevel().getWorldSize();
    const sf::Vector2f starts[] = {
        {600.f, r}, {r, 300.f}, {600.f, world.y - r}, {world.x - r, 300.f}};
    const sf::Vector2f velocities[] = {
        {testSpeed, 0.f}, {0.f, testSpeed}, {-testSpeed, 0.f}, {0.f, -testSpeed}};
    for (int i = 0; i < 4; ++i)
    {
        BallsLevel level = emptyLevel();
        level.addBall(starts[i], velocities[i]);
        run(level, 0.5f);
        EXPECT_EQ(level.getBall(0).getHitCount(), 0)
            << "a ball touching a wall at " << labtesting::text(starts[i])
            << " and sliding along it is not hitting it (touching is not colliding)";
        EXPECT_VEC_NEAR(level.getBall(0).getVelocity(), velocities[i], 0.001f);
    }
}

TEST(Task1BounceOffTheWalls, ABallAlreadyOnItsWayBackIsNotTurnedIntoTheWall)
{
    // Sticking out past the right (bottom) wall but already moving away from it, e.g. pushed
    // there by another ball: it must keep moving away. A sign flip (velocity = -velocity)
    // would turn it back into the wall, where it sticks, shaking.
    const float r = radius();
    const sf::Vector2f world = emptyLevel().getWorldSize();
    const sf::Vector2f starts[] = {{world.x - r + 4.f, 300.f}, {600.f, world.y - r + 4.f}};
    const sf::Vector2f velocities[] = {{-testSpeed, 0.f}, {0.f, -testSpeed}};
    for (int i = 0; i < 2; ++i)
    {
        BallsLevel level = emptyLevel();
        level.addBall(starts[i], velocities[i]);
        hitbox::simulate(level, 1);
        EXPECT_VEC_NEAR(level.getBall(0).getVelocity(), velocities[i], 0.001f)
            << "a ball at " << labtesting::text(starts[i]) << " moving away from the wall";
    }
}

TEST(Task1BounceOffTheWalls, EachWallBounceIsAHitTheBallIsToldAbout)
{
    // collisionResponse(nullptr) once per bounce, so the ball flashes: off a side wall and
    // off the top.
    const sf::Vector2f directions[] = {{-1.f, 0.f}, {0.f, -1.f}};
    for (sf::Vector2f direction : directions)
    {
        BallsLevel level = emptyLevel();
        level.addBall(middle, direction * testSpeed);
        const sf::Vector2f toWall = level.getWorldSize() / 2.f - sf::Vector2f(radius(), radius());
        run(level,
            std::abs(hitbox::dot(hitbox::toVec2(toWall), hitbox::toVec2(direction))) / testSpeed +
                0.5f);
        EXPECT_EQ(level.getBall(0).getHitCount(), 1)
            << "a ball sent towards " << labtesting::text(direction) << " hit one wall once";
    }
}

namespace
{
// Task 2's tests count hits between balls only: a lone ball far from the others, at rest in
// the middle, gets every hit that is not another ball's (task 1's walls, right or wrong), and
// pairHits leaves those out. So a mistake in task 1 never costs task 2.
void addLoneBall(BallsLevel& level)
{
    level.addBall(middle + sf::Vector2f{0.f, 4.f * radius()}, {});
}

int pairHits(const BallsLevel& level, int ball)
{
    return level.getBall(ball).getHitCount() -
           level.getBall(level.getBallCount() - 1).getHitCount();
}
} // namespace

TEST(Task2TestEachPairWithTheBoundingCircle, OverlappingBallsAreBothToldAboutTheHit)
{
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{1.4f, 0.35f} * radius(), {}); // overlapping by ~0.55 r
    addLoneBall(level);
    hitbox::simulate(level, 1);
    EXPECT_EQ(pairHits(level, 0), 1);
    EXPECT_EQ(pairHits(level, 1), 1);
}

TEST(Task2TestEachPairWithTheBoundingCircle, BallsOnlyTouchingAreNotAHit)
{
    // Touching is not colliding (the framework's edge rule): centres exactly 2r apart.
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{2.f * radius(), 0.f}, {});
    addLoneBall(level);
    hitbox::simulate(level, 1);
    EXPECT_EQ(pairHits(level, 0), 0);
    EXPECT_EQ(pairHits(level, 1), 0);
}

TEST(Task2TestEachPairWithTheBoundingCircle, DiagonalNeighboursWhoseBoxesOverlapAreNotAHit)
{
    // Their boxes overlap at the corners but the circles do not: a circle test, not a box test.
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{1.6f * radius(), 1.6f * radius()}, {});
    addLoneBall(level);
    hitbox::simulate(level, 1);
    EXPECT_EQ(pairHits(level, 0), 0);
}

TEST(Task2TestEachPairWithTheBoundingCircle, EveryPairIsTested)
{
    // Three balls in a row, each overlapping the next: 0-1 and 1-2 hit, 0-2 does not.
    const float r = radius();
    BallsLevel level = emptyLevel();
    level.addBall(middle, {});
    level.addBall(middle + sf::Vector2f{1.8f * r, 0.f}, {});
    level.addBall(middle + sf::Vector2f{3.6f * r, 0.f}, {});
    level.addBall(middle - sf::Vector2f{3.f * r, 0.f}, {}); // alone
    addLoneBall(level);
    hitbox::simulate(level, 1);
    EXPECT_EQ(pairHits(level, 0), 1);
    EXPECT_EQ(pairHits(level, 1), 2);
    EXPECT_EQ(pairHits(level, 2), 1);
    EXPECT_EQ(pairHits(level, 3), 0);
}

// Task 3's tests call bounceApart (task 3's code) on their own balls, moved by the test
// itself, so they need neither the wall bounce (task 1) nor the pair test (task 2): a
// mistake there costs only its own task. Every step: both balls move, then bounceApart.
namespace
{
void stepApart(std::vector<Ball>& balls, int steps)
{
    for (int step = 0; step < steps; ++step)
    {
        for (Ball& ball : balls)
            ball.move(ball.getVelocity() * hitbox::stepSeconds);
        for (std::size_t i = 0; i < balls.size(); ++i)
            for (std::size_t j = i + 1; j < balls.size(); ++j)
                bounceApart(balls[i], balls[j]);
    }
}

int stepsFor(float seconds)
{
    return static_cast<int>(seconds * hitbox::stepsPerSecond);
}
} // namespace

TEST(Task3BounceApartLikeBilliardBalls, HeadOnBallsReverseAfterContactAndNeverOverlap)
{
    // The lecture's example: two balls on one line, flying at each other.
    std::vector<Ball> balls{
        Ball(middle - sf::Vector2f{300.f, 0.f}, {testSpeed, 0.f}, sf::Color::White),
        Ball(middle + sf::Vector2f{300.f, 0.f}, {-testSpeed, 0.f}, sf::Color::White)};
    float worstOverlap = 0.f;
    int stepsSinceTheyMet = -1;
    // Until a quarter of a second after they meet: long enough to bounce.
    for (int step = 0; step < 4 * 120 && stepsSinceTheyMet < 30; ++step)
    {
        stepApart(balls, 1);
        const float overlap = overlapOf(balls[0], balls[1]);
        worstOverlap = std::max(worstOverlap, overlap);
        if (stepsSinceTheyMet >= 0 || overlap > -1.f)
            ++stepsSinceTheyMet;
    }
    ASSERT_GE(stepsSinceTheyMet, 0) << "the balls should meet within four seconds";
    EXPECT_LE(worstOverlap, overlapTolerance) << "after a step the balls may not overlap";
    EXPECT_FLOAT_EQ(balls[0].getVelocity().x, -testSpeed) << "the left ball goes back left";
    EXPECT_FLOAT_EQ(balls[1].getVelocity().x, testSpeed) << "the right ball goes back right";
}

TEST(Task3BounceApartLikeBilliardBalls, MovingBallHittingABallAtRestStopsAndPassesItsSpeedOn)
{
    // Equal masses, elastic, head-on: the velocities are exchanged (Newton's cradle).
    const float gap = 100.f; // between the balls' edges
    std::vector<Ball> balls{
        Ball(middle - sf::Vector2f{2.f * radius() + gap, 0.f}, {testSpeed, 0.f}, sf::Color::White),
        Ball(middle, {}, sf::Color::White)};
    stepApart(balls, stepsFor(gap / testSpeed + 0.3f));
    EXPECT_VEC_NEAR(balls[0].getVelocity(), sf::Vector2f(0.f, 0.f), 0.01f)
        << "the moving ball should stop dead";
    EXPECT_VEC_NEAR(balls[1].getVelocity(), sf::Vector2f(testSpeed, 0.f), 0.01f)
        << "the ball at rest should leave at the moving ball's speed";
}

TEST(Task3BounceApartLikeBilliardBalls, GlancingHitKeepsMomentumAndEnergy)
{
    // Both drift down at the same speed and close in along x, one radius apart sideways,
    // so they meet off-centre (the line between the centres 30 degrees from their path).
    const float r = radius();
    const sf::Vector2f startA{testSpeed, 0.2f * testSpeed};
    const sf::Vector2f startB{-0.5f * testSpeed, 0.2f * testSpeed};
    std::vector<Ball> balls{Ball(middle - sf::Vector2f{4.f * r, r / 2.f}, startA, sf::Color::White),
                            Ball(middle + sf::Vector2f{0.f, r / 2.f}, startB, sf::Color::White)};
    // They touch when 2r * cos(30 degrees) apart along x, closing at 1.5 * testSpeed.
    const float secondsToMeet = (4.f - std::sqrt(3.f)) * r / (1.5f * testSpeed);
    stepApart(balls, stepsFor(secondsToMeet + 0.2f));
    const hitbox::Vec2 a = hitbox::toVec2(balls[0].getVelocity());
    const hitbox::Vec2 b = hitbox::toVec2(balls[1].getVelocity());
    const hitbox::Vec2 startAVec = hitbox::toVec2(startA);
    const hitbox::Vec2 startBVec = hitbox::toVec2(startB);
    ASSERT_GT(hitbox::length(a - startAVec), 0.1f * testSpeed)
        << "the hit should change the velocities";
    EXPECT_VEC_NEAR(balls[0].getVelocity() + balls[1].getVelocity(), startA + startB, 0.05f)
        << "total momentum is kept";
    EXPECT_NEAR(hitbox::dot(a, a) + hitbox::dot(b, b),
                hitbox::dot(startAVec, startAVec) + hitbox::dot(startBVec, startBVec), 1.f)
        << "total kinetic energy is kept (an elastic collision)";
}

TEST(Task3BounceApartLikeBilliardBalls, OverlappingBallsArePushedApartUntilTheyTouch)
{
    const float r = radius();
    Ball first(middle, {}, sf::Color::White);
    Ball second(middle + sf::Vector2f{r, 0.f}, {}, sf::Color::White); // overlapping by one radius
    bounceApart(first, second);
    EXPECT_NEAR(overlapOf(first, second), 0.f, overlapTolerance)
        << "pushed apart until they just touch";
    EXPECT_NEAR(first.getPosition().x + second.getPosition().x, 2.f * middle.x + r, 0.01f)
        << "each ball moves half the overlap, so their midpoint stays put";
}

TEST(Task3BounceApartLikeBilliardBalls, BallsAlreadyMovingApartAreNotPulledBack)
{
    // Overlapping but separating (e.g. pushed together by a wall): no sticking together.
    Ball first(middle, {-testSpeed, 0.f}, sf::Color::White);
    Ball second(middle + sf::Vector2f{1.4f * radius(), 0.f}, {testSpeed, 0.f}, sf::Color::White);
    bounceApart(first, second);
    EXPECT_FLOAT_EQ(first.getVelocity().x, -testSpeed);
    EXPECT_FLOAT_EQ(second.getVelocity().x, testSpeed);
}

TEST(Task3BounceApartLikeBilliardBalls, OverlappingBallsDriftingApartKeepTheirVelocities)
{
    // Overlapping but already separating, however slowly (0.4 px/s): pushed apart, not bounced.
    Ball first(middle, {-0.2f, 0.f}, sf::Color::White);
    Ball second(middle + sf::Vector2f{1.4f * radius(), 0.f}, {0.2f, 0.f}, sf::Color::White);
    bounceApart(first, second);
    EXPECT_FLOAT_EQ(first.getVelocity().x, -0.2f);
    EXPECT_FLOAT_EQ(second.getVelocity().x, 0.2f);
}

TEST(Task3BounceApartLikeBilliardBalls, BallsOnlyTouchingAreLeftAlone)
{
    // The edge rule: centres exactly 2r apart, closing in: touching is not colliding yet.
    Ball first(middle, {testSpeed, 0.f}, sf::Color::White);
    Ball second(middle + sf::Vector2f{2.f * radius(), 0.f}, {-testSpeed, 0.f}, sf::Color::White);
    bounceApart(first, second);
    EXPECT_FLOAT_EQ(first.getVelocity().x, testSpeed);
    EXPECT_FLOAT_EQ(second.getVelocity().x, -testSpeed);
}

TEST(Task3BounceApartLikeBilliardBalls, ACrowdOfBallsNeverOverlaps)
{
    // Twenty balls in a 5 x 4 grid, flying in as many directions, in a world with no walls
    // (the test moves them itself), for two seconds.
    const float r = radius();
    const sf::Vector2f world{12.f * r * 5.f, 12.f * r * 4.f};
    std::vector<Ball> balls;
    for (int i = 0; i < 20; ++i)
    {
        const labtesting::CrowdStart start = labtesting::crowdStart(i, 5, 4, world, testSpeed);
        balls.emplace_back(start.position, start.velocity, sf::Color::White);
    }
    // In a crowd a ball pushed out of one ball can be pushed into another in the same
    // step; allow what two balls close in one step.
    const float crowdTolerance = 2.f * testSpeed * hitbox::stepSeconds + overlapTolerance;
    for (int step = 0; step < 2 * 120; ++step)
    {
        stepApart(balls, 1);
        for (std::size_t i = 0; i < balls.size(); ++i)
            for (std::size_t j = i + 1; j < balls.size(); ++j)
                ASSERT_LE(overlapOf(balls[i], balls[j]), crowdTolerance)
                    << "balls " << i << " and " << j << " at step " << step;
    }
}
