// Grading tests for lab 7 (swept circles). Each suite checks one task of README.md.
#include "PoolLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Vec2.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{

const hitbox::Box bigTable{0.f, 0.f, 4000.f, 1000.f};
const float radius = 14.f;

Ball ballAt(hitbox::Vec2 center, hitbox::Vec2 velocity = {0.f, 0.f})
{
    return {{center, radius}, velocity, sf::Color::White};
}

void step(PoolLevel& level, int steps)
{
    for (int i = 0; i < steps; ++i)
        level.update(hitbox::stepSeconds);
}

bool anyTwoBallsOverlap(const PoolLevel& level)
{
    const std::vector<Ball>& balls = level.getBalls();
    for (std::size_t a = 0; a < balls.size(); ++a)
        for (std::size_t b = a + 1; b < balls.size(); ++b)
        {
            // A hair of overlap is float rounding at the moment of touching, not a miss.
            hitbox::Circle smaller = balls[a].shape;
            smaller.radius -= 0.01f;
            if (hitbox::circleVsCircle(smaller, balls[b].shape))
                return true;
        }
    return false;
}

} // namespace

TEST(Task1TimeOfImpact, FindsTheFirstOfTwoBallsInTheWay)
{
    // The nearer ball (index 2) is listed last: the earliest time must win, not list order.
    PoolLevel level(
        {ballAt({100.f, 500.f}, {6000.f, 0.f}), ballAt({400.f, 500.f}), ballAt({250.f, 500.f})},
        bigTable);
    const BallEvent event = level.findFirstEvent(0.1f); // a 600 px move
    ASSERT_TRUE(event.hit);
    EXPECT_EQ(event.first, 0u);
    EXPECT_EQ(event.second, 2u);
    EXPECT_EQ(event.cushion, -1);
    // The centres touch 28 px apart: after 150 - 28 = 122 of the 600 px.
    EXPECT_NEAR(event.time, 122.f / 600.f, 1e-4f);
    EXPECT_NEAR(event.normal.x, -1.f, 1e-5f);
}

TEST(Task1TimeOfImpact, BothBallsMovingMeetInTheMiddle)
{
    PoolLevel level({ballAt({100.f, 500.f}, {1000.f, 0.f}), ballAt({300.f, 500.f}, {-1000.f, 0.f})},
                    bigTable);
    const BallEvent event = level.findFirstEvent(0.1f); // each moves 100 px
    ASSERT_TRUE(event.hit);
    // They close 200 px in the step and need to close 200 - 28 = 172.
    EXPECT_NEAR(event.time, 172.f / 200.f, 1e-4f);
}

TEST(Task1TimeOfImpact, AFastBallNeverPassesThroughAnother)
{
    for (float speed : {3000.f, 20000.f, 100000.f, 1000000.f})
    {
        // A table 20 000 px long, so even at 10^6 px/s nothing reaches a cushion.
        PoolLevel level({ballAt({100.f, 500.f}, {speed, 0.f}), ballAt({700.f, 500.f})},
                        {0.f, 0.f, 20000.f, 1000.f});
        level.setFriction(false);
        step(level, 30); // long enough to reach the other ball at every speed here
        const std::vector<Ball>& balls = level.getBalls();
        EXPECT_LT(balls[0].shape.center.x, balls[1].shape.center.x) << "at " << speed << " px/s";
        EXPECT_FALSE(anyTwoBallsOverlap(level)) << "at " << speed;
    }
}

TEST(Task2ElasticBounce, HeadOnTheMovingBallStopsAndTheOtherTakesItsSpeed)
{
    const auto [first, second] = PoolLevel::bounceBalls({300.f, 0.f}, {0.f, 0.f}, {-1.f, 0.f});
    EXPECT_NEAR(first.x, 0.f, 1e-4f);
    EXPECT_NEAR(second.x, 300.f, 1e-4f);
    EXPECT_NEAR(first.y, 0.f, 1e-4f);
    EXPECT_NEAR(second.y, 0.f, 1e-4f);
}

TEST(Task2ElasticBounce, AGlancingHitSendsTheBallsOffAtRightAngles)
{
    // Struck at 45 degrees: the cue ball keeps the part along the surface.
    const float half = 1.f / std::sqrt(2.f);
    const auto [first, second] = PoolLevel::bounceBalls({400.f, 0.f}, {0.f, 0.f}, {-half, half});
    EXPECT_NEAR(hitbox::dot(first, second), 0.f, 1e-2f);
    EXPECT_NEAR(first.x, 200.f, 1e-3f);
    EXPECT_NEAR(first.y, 200.f, 1e-3f);
    EXPECT_NEAR(second.x, 200.f, 1e-3f);
    EXPECT_NEAR(second.y, -200.f, 1e-3f);
}

TEST(Task2ElasticBounce, AFastBallHandsAllItsSpeedToTheBallItHits)
{
    for (float speed : {3000.f, 100000.f, 1000000.f})
    {
        PoolLevel level({ballAt({100.f, 500.f}, {speed, 0.f}), ballAt({700.f, 500.f})},
                        {0.f, 0.f, 20000.f, 1000.f});
        level.setFriction(false);
        // Step until the struck ball moves (at most one second).
        for (int i = 0; i < 120 && level.getBalls()[1].velocity.x == 0.f; ++i)
            step(level, 1);
        const std::vector<Ball>& balls = level.getBalls();
        EXPECT_NEAR(balls[1].velocity.x, speed, 1e-3f * speed) << "at " << speed;
        EXPECT_NEAR(balls[0].velocity.x, 0.f, 1e-3f * speed) << "head on: the cue ball stops";
        EXPECT_LT(balls[0].shape.center.x, balls[1].shape.center.x) << "at " << speed;
    }
}

TEST(Task2ElasticBounce, BallsAlreadyMovingApartAreLeftAlone)
{
    const auto [first, second] = PoolLevel::bounceBalls({-50.f, 0.f}, {20.f, 0.f}, {-1.f, 0.f});
    EXPECT_EQ(first, hitbox::Vec2(-50.f, 0.f));
    EXPECT_EQ(second, hitbox::Vec2(20.f, 0.f));
}

TEST(Task2ElasticBounce, MomentumAndEnergyAreKeptThroughTheBreak)
{
    PoolLevel level; // the lab's break, without rolling friction
    level.setFriction(false);
    auto totals = [&]()
    {
        hitbox::Vec2 momentum;
        float energy = 0.f;
        for (const Ball& ball : level.getBalls())
        {
            momentum += ball.velocity;
            energy += hitbox::dot(ball.velocity, ball.velocity);
        }
        return std::make_pair(momentum, energy);
    };
    const auto [momentumBefore, energyBefore] = totals();
    step(level, 9); // the cue ball reaches the rack; no ball reaches a cushion yet
    const auto [momentumAfter, energyAfter] = totals();
    EXPECT_NEAR(momentumAfter.x, momentumBefore.x, 0.001f * energyBefore / 6000.f);
    EXPECT_NEAR(momentumAfter.y, momentumBefore.y, 1.f);
    EXPECT_NEAR(energyAfter, energyBefore, 0.001f * energyBefore);
    EXPECT_LT(std::abs(level.getBalls()[0].velocity.x), 5000.f) << "the cue ball hit the rack";
}

TEST(Task3Cushions, AFastBallBouncesOffTheCushionAndStaysOnTheTable)
{
    // Up to 100 000 px/s (833 px a step) the ball meets the cushion once in a step.
    for (float speed : {500.f, 20000.f, 100000.f})
    {
        PoolLevel level({ballAt({500.f, 500.f}, {speed, 0.f})}, {100.f, 100.f, 800.f, 800.f});
        level.setFriction(false);
        for (int i = 0; i < 240 && level.getBalls()[0].velocity.x > 0.f; ++i)
        {
            step(level, 1);
            ASSERT_TRUE(hitbox::pointInBox(level.getBalls()[0].shape.center, level.getTable()))
                << "at " << speed;
        }
        const Ball& ball = level.getBalls()[0];
        EXPECT_NEAR(ball.velocity.x, -0.9f * speed, 0.001f * speed) << "90 % restitution";
        EXPECT_NEAR(ball.shape.center.y, 500.f, 1e-3f);
    }
}

TEST(Task3Cushions, AtAMillionPixelsASecondItBouncesSeveralTimesInOneStep)
{
    // 8 333 px a step on a table 800 px wide: the rest of the step goes round again after
    // each bounce, and every bounce keeps 90 % of the speed.
    PoolLevel level({ballAt({500.f, 500.f}, {1000000.f, 0.f})}, {100.f, 100.f, 800.f, 800.f});
    level.setFriction(false);
    for (int i = 0; i < 10; ++i)
    {
        step(level, 1);
        ASSERT_TRUE(hitbox::pointInBox(level.getBalls()[0].shape.center, level.getTable()));
    }
    EXPECT_LT(std::abs(level.getBalls()[0].velocity.x), 0.9f * 1000000.f);
}

TEST(Task3Cushions, NoBallEverLeavesTheTableDuringTheBreak)
{
    PoolLevel level;
    for (int i = 0; i < 120 * 6; ++i)
    {
        level.update(hitbox::stepSeconds);
        for (const Ball& ball : level.getBalls())
        {
            const hitbox::Box table = level.getTable();
            const hitbox::Box inner{table.left + radius - 0.01f, table.top + radius - 0.01f,
                                    table.width - 2.f * radius + 0.02f,
                                    table.height - 2.f * radius + 0.02f};
            ASSERT_TRUE(hitbox::pointInBox(ball.shape.center, inner)) << "step " << i;
        }
        ASSERT_FALSE(anyTwoBallsOverlap(level)) << "step " << i;
    }
}
