// Grading tests for lab 7 (swept circles). Each suite checks one task of README.md.
#include "labs/07_swept_circles/PoolChecks.h"

#include "PoolLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Vec2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

using namespace poolchecks;

const hitbox::Box bigTable{0.f, 0.f, 4000.f, 1000.f};

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

TEST(Task1TimeOfImpact, TheEarliestWinsInEitherListOrder)
{
    // The nearer ball listed first this time: a later hit found afterwards must not replace it.
    PoolLevel level(
        {ballAt({100.f, 500.f}, {6000.f, 0.f}), ballAt({250.f, 500.f}), ballAt({400.f, 500.f})},
        bigTable);
    const BallEvent event = level.findFirstEvent(0.1f);
    ASSERT_TRUE(event.hit);
    EXPECT_EQ(event.second, 1u);
    EXPECT_NEAR(event.time, 122.f / 600.f, 1e-4f);
}

TEST(Task1TimeOfImpact, TouchingBallsCountByHowTheyMoveRelativeToEachOther)
{
    // Two balls touching (a hair of overlap left by rounding), both moving left. What counts
    // is their relative velocity: the one behind faster is a hit now; the one in front
    // faster is already leaving.
    const hitbox::Vec2 left{300.f, 500.f};
    const hitbox::Vec2 right{300.f + 2.f * radius - 0.001f, 500.f};
    PoolLevel catching({ballAt(left, {-100.f, 0.f}), ballAt(right, {-300.f, 0.f})}, bigTable);
    const BallEvent hit = catching.findFirstEvent(0.01f);
    EXPECT_TRUE(hit.hit) << "the ball behind is faster: it pushes into the one in front";
    EXPECT_NEAR(hit.time, 0.f, 1e-4f);
    PoolLevel leaving({ballAt(left, {-300.f, 0.f}), ballAt(right, {-100.f, 0.f})}, bigTable);
    EXPECT_FALSE(leaving.findFirstEvent(0.01f).hit) << "the ball in front is faster: they part";
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
        // Step until the balls meet (at most 12 steps at the slowest speed), and no further:
        // after that the struck ball would run on to a cushion, which is task 3's business.
        const auto notMetYet = [&level]
        {
            const std::vector<Ball>& balls = level.getBalls();
            return balls[1].velocity.x == 0.f &&
                   balls[1].shape.center.x - balls[0].shape.center.x > 2.f * radius + 0.01f;
        };
        for (int i = 0; i < 30 && notMetYet(); ++i)
            step(level, 1);
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
        const auto [first, second] = PoolLevel::bounceBalls({speed, 0.f}, {0.f, 0.f}, {-1.f, 0.f});
        EXPECT_NEAR(second.x, speed, 1e-5f * speed) << "at " << speed;
        EXPECT_NEAR(first.x, 0.f, 1e-5f * speed) << "head on: the cue ball stops";
    }
}

TEST(Task2ElasticBounce, BallsAlreadyMovingApartAreLeftAlone)
{
    const auto [first, second] = PoolLevel::bounceBalls({-50.f, 0.f}, {20.f, 0.f}, {-1.f, 0.f});
    EXPECT_EQ(first, hitbox::Vec2(-50.f, 0.f));
    EXPECT_EQ(second, hitbox::Vec2(20.f, 0.f));
}

TEST(Task2ElasticBounce, BallsDriftingApartSlowlyAreLeftAlone)
{
    // Parting at half a pixel a second is still parting: a bounce would turn them round.
    const auto [first, second] = PoolLevel::bounceBalls({-0.5f, 0.f}, {0.f, 0.f}, {-1.f, 0.f});
    EXPECT_EQ(first, hitbox::Vec2(-0.5f, 0.f));
    EXPECT_EQ(second, hitbox::Vec2(0.f, 0.f));
}

TEST(Task2ElasticBounce, EveryBounceKeepsMomentumAndEnergyAndReversesTheClosingSpeed)
{
    // Seeded velocities and normals in every direction (the break's many kinds of hit).
    std::mt19937 random(7);
    std::uniform_real_distribution<float> component(-1000.f, 1000.f);
    std::uniform_real_distribution<float> angle(0.f, 2.f * hitbox::pi);
    for (int bounce = 0; bounce < 200; ++bounce)
    {
        const hitbox::Vec2 first{component(random), component(random)};
        const hitbox::Vec2 second{component(random), component(random)};
        const float direction = angle(random);
        const hitbox::Vec2 normal{std::cos(direction), std::sin(direction)};
        const auto [firstAfter, secondAfter] = PoolLevel::bounceBalls(first, second, normal);
        const hitbox::Vec2 momentumBefore = first + second;
        const hitbox::Vec2 momentumAfter = firstAfter + secondAfter;
        const float energyBefore = hitbox::dot(first, first) + hitbox::dot(second, second);
        const float energyAfter =
            hitbox::dot(firstAfter, firstAfter) + hitbox::dot(secondAfter, secondAfter);
        ASSERT_NEAR(momentumAfter.x, momentumBefore.x, 0.01f) << "bounce " << bounce;
        ASSERT_NEAR(momentumAfter.y, momentumBefore.y, 0.01f) << "bounce " << bounce;
        ASSERT_NEAR(energyAfter, energyBefore, 1e-4f * energyBefore) << "bounce " << bounce;
        // Closing in along the normal: they leave at the same speed; already apart: unchanged.
        const float closing = hitbox::dot(first - second, normal);
        ASSERT_NEAR(hitbox::dot(firstAfter - secondAfter, normal), std::fabs(closing), 0.01f)
            << "bounce " << bounce;
    }
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

TEST(Task3Cushions, NoBallEverLeavesTheTableInAnyDirection)
{
    // One ball at a time, so this needs no ball-ball collision (task 1) to pass.
    const hitbox::Box table{100.f, 100.f, 800.f, 600.f};
    const hitbox::Box inner = centreBounds(table);
    for (int degrees = 7; degrees < 360; degrees += 15)
        for (float speed : {500.f, 6000.f, 100000.f})
        {
            const float angle = static_cast<float>(degrees) * hitbox::pi / 180.f;
            PoolLevel level(
                {ballAt({450.f, 400.f}, {speed * std::cos(angle), speed * std::sin(angle)})},
                table);
            level.setFriction(false);
            for (int i = 0; i < 240; ++i)
            {
                level.update(hitbox::stepSeconds);
                ASSERT_TRUE(hitbox::pointInBox(level.getBalls()[0].shape.center, inner))
                    << degrees << " degrees at " << speed << " px/s, step " << i;
            }
        }
}

TEST(Task3Cushions, ATouchingBallBouncesOnlyWhenMovingIntoTheCushion)
{
    // The right cushion starts at x = 900; a ball at x = 886 touches it exactly.
    const hitbox::Box table{100.f, 100.f, 800.f, 800.f};
    PoolLevel sliding({ballAt({886.f, 300.f}, {0.f, 300.f})}, table);
    sliding.setFriction(false);
    step(sliding, 60);
    EXPECT_EQ(sliding.getBalls()[0].velocity, hitbox::Vec2(0.f, 300.f))
        << "touching is not a collision: sliding along the cushion, the ball keeps its speed";
    EXPECT_NEAR(sliding.getBalls()[0].shape.center.y, 450.f, 0.01f);

    PoolLevel pushing({ballAt({886.f, 300.f}, {300.f, 0.f})}, table);
    pushing.setFriction(false);
    step(pushing, 1);
    EXPECT_NEAR(pushing.getBalls()[0].velocity.x, -270.f, 0.01f)
        << "moving into the cushion from touching: it bounces at once";
    EXPECT_LE(pushing.getBalls()[0].shape.center.x, 886.f);
}
