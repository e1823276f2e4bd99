// Hidden variants of lab 2's grading tests: the same behaviour as BallsGradingTests.cpp with
// other numbers and positions. The instructor's build and the class grader run them; the
// student handout leaves tests/labs-hidden/ out, so no one can tune an answer to them.
#include "labs/LabTesting.h"

#include "Ball.h"
#include "BallsLevel.h"

#include "hitbox/app/App.h"

#include <gtest/gtest.h>

namespace
{
float radius()
{
    return Ball({}, {}, sf::Color::White).getRadius();
}
} // namespace

TEST(Task1BounceOffTheWalls, HiddenBallFromTheCornerComesBackFromBothWalls)
{
    // Into the bottom-right corner at an odd speed: both parts of the velocity turn round.
    BallsLevel level;
    level.removeAllBalls();
    const sf::Vector2f world = level.getWorldSize();
    const float r = radius();
    level.addBall(world - sf::Vector2f{r + 20.f, r + 13.f}, {173.f, 211.f});
    hitbox::simulate(level, 60); // half a second: both walls reached, the far ones not
    EXPECT_VEC_NEAR(level.getBall(0).getVelocity(), sf::Vector2f(-173.f, -211.f), 0.01f);
}

TEST(Task2TestEachPairWithTheBoundingCircle, HiddenBallsBarelyOverlappingOnADiagonalHit)
{
    // Centres 1.95 r apart on a slant: the circles overlap a little, so it is a hit.
    BallsLevel level;
    level.removeAllBalls();
    const float r = radius();
    const sf::Vector2f start{317.f, 241.f};
    level.addBall(start, {});
    level.addBall(start + sf::Vector2f{0.6f, 0.8f} * (1.95f * r), {});
    level.addBall(start + sf::Vector2f{6.f * r, 0.f}, {}); // alone: counts any hit but a ball's
    hitbox::simulate(level, 1);
    const int alone = level.getBall(2).getHitCount();
    EXPECT_EQ(level.getBall(0).getHitCount() - alone, 1);
    EXPECT_EQ(level.getBall(1).getHitCount() - alone, 1);
}
