// Hidden variants of lab 7's grading tests: the same behaviour as PoolGradingTests.cpp with
// other numbers, directions and positions. The instructor's build and the class grader run
// them; the student handout leaves tests/labs-hidden/ out, so no one can tune an answer to them.
#include "labs/07_swept_circles/PoolChecks.h"

#include "PoolLevel.h"

#include "hitbox/app/Loop.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Vec2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using namespace poolchecks;
} // namespace

TEST(Task1TimeOfImpact, HiddenTheFirstPairToMeetNeedNotIncludeTheCueBall)
{
    // The cue ball hits ball 3 in this step, but balls 1 and 2 on another row meet earlier:
    // an answer that only sweeps the cue ball, or keeps the first pair found, reports 0 and 3.
    const hitbox::Box table{0.f, 0.f, 4000.f, 1000.f};
    PoolLevel level({ballAt({100.f, 200.f}, {3000.f, 0.f}), ballAt({900.f, 700.f}, {-2000.f, 0.f}),
                     ballAt({700.f, 700.f}, {1000.f, 0.f}), ballAt({400.f, 200.f})},
                    table);
    const BallEvent event = level.findFirstEvent(0.1f);
    ASSERT_TRUE(event.hit);
    EXPECT_EQ(event.first, 1u);
    EXPECT_EQ(event.second, 2u);
    EXPECT_EQ(event.cushion, -1);
    // They close 3 000 px/s * 0.1 s = 300 px and need 200 - 28 = 172 of it.
    EXPECT_NEAR(event.time, 172.f / 300.f, 1e-4f);
    // Out of ball 2 (on the left) towards ball 1: to the right this time.
    EXPECT_NEAR(event.normal.x, 1.f, 1e-5f);
    EXPECT_NEAR(event.normal.y, 0.f, 1e-5f);
}

TEST(Task1TimeOfImpact, HiddenBallsClosingVerticallyAtDifferentSpeeds)
{
    // Ball 1 falls at 900 px/s onto ball 2 rising at 300 px/s: both moves count, and the
    // normal points up, out of the lower ball. A still ball far off is listed first.
    const hitbox::Box table{0.f, 0.f, 4000.f, 1000.f};
    PoolLevel level({ballAt({3000.f, 800.f}), ballAt({600.f, 200.f}, {0.f, 900.f}),
                     ballAt({600.f, 450.f}, {0.f, -300.f})},
                    table);
    const BallEvent event = level.findFirstEvent(0.25f); // they close 300 px
    ASSERT_TRUE(event.hit);
    EXPECT_EQ(event.first, 1u);
    EXPECT_EQ(event.second, 2u);
    EXPECT_NEAR(event.time, (250.f - 28.f) / 300.f, 1e-4f);
    EXPECT_NEAR(event.normal.x, 0.f, 1e-5f);
    EXPECT_NEAR(event.normal.y, -1.f, 1e-5f);
}

TEST(Task1TimeOfImpact, HiddenAnOffCentreDiagonalHitAndAGrazeThatIsNoHit)
{
    // Moving along (0.6, 0.8) past a ball whose centre lies 14 px off the line: the centres
    // touch sqrt(28^2 - 14^2) px before the closest point. A ball whose centre lies exactly
    // 28 px off the line only touches it in passing: touching is not a collision.
    const hitbox::Box table{0.f, 0.f, 4000.f, 4000.f};
    const hitbox::Vec2 start{100.f, 100.f};
    const hitbox::Vec2 direction{0.6f, 0.8f};
    const hitbox::Vec2 across{-0.8f, 0.6f};
    const hitbox::Vec2 struck = start + direction * 500.f + across * 14.f;
    PoolLevel level({ballAt(start, direction * 5000.f), ballAt(struck)}, table);
    const BallEvent event = level.findFirstEvent(0.2f); // a 1 000 px move
    ASSERT_TRUE(event.hit);
    EXPECT_EQ(event.second, 1u);
    const float along = 500.f - std::sqrt(28.f * 28.f - 14.f * 14.f);
    EXPECT_NEAR(event.time, along / 1000.f, 1e-4f);
    const hitbox::Vec2 touching = start + direction * along;
    const hitbox::Vec2 normal = (touching - struck) / 28.f;
    EXPECT_NEAR(event.normal.x, normal.x, 1e-3f);
    EXPECT_NEAR(event.normal.y, normal.y, 1e-3f);

    PoolLevel grazing({ballAt({100.f, 500.f}, {5000.f, 0.f}), ballAt({400.f, 528.f})}, table);
    EXPECT_FALSE(grazing.findFirstEvent(0.1f).hit) << "centres exactly 28 px apart: no overlap";
}

TEST(Task1TimeOfImpact, HiddenTouchingBallsMovingDownCountByTheirRelativeVelocity)
{
    // Touching (a hair of overlap) on a vertical line, both moving down. The upper one
    // faster pushes into the lower one; the lower one faster leaves; at the same speed they
    // travel together. Each ball's own velocity says "into the other" for one of them, so
    // only the relative velocity gets all three right.
    const hitbox::Box table{0.f, 0.f, 4000.f, 1000.f};
    const hitbox::Vec2 upper{700.f, 300.f};
    const hitbox::Vec2 lower{700.f, 300.f + 2.f * radius - 0.001f};
    PoolLevel catching({ballAt(upper, {0.f, 450.f}), ballAt(lower, {0.f, 120.f})}, table);
    const BallEvent hit = catching.findFirstEvent(0.02f);
    EXPECT_TRUE(hit.hit) << "the upper ball is faster: it pushes into the lower one";
    EXPECT_NEAR(hit.time, 0.f, 1e-4f);
    PoolLevel leaving({ballAt(upper, {0.f, 120.f}), ballAt(lower, {0.f, 450.f})}, table);
    EXPECT_FALSE(leaving.findFirstEvent(0.02f).hit) << "the lower ball is faster: they part";
    PoolLevel together({ballAt(upper, {0.f, 250.f}), ballAt(lower, {0.f, 250.f})}, table);
    EXPECT_FALSE(together.findFirstEvent(0.02f).hit) << "same velocity: they never close in";
}

TEST(Task1TimeOfImpact, HiddenAFastDiagonalShotNeverPassesThroughAnOffCentreBall)
{
    // Up and to the right, at speeds the visible test does not use, into a ball 10 px off the
    // line of the shot: the cue ball must stop touching it, never inside or beyond it.
    const hitbox::Vec2 direction{0.28f, -0.96f};
    const hitbox::Vec2 across{0.96f, 0.28f};
    for (float speed : {4500.f, 50000.f, 700000.f})
    {
        const hitbox::Vec2 start{300.f, 19500.f};
        const hitbox::Vec2 target = start + direction * 900.f + across * 10.f;
        PoolLevel level({ballAt(start, direction * speed), ballAt(target)},
                        {0.f, 0.f, 20000.f, 20000.f});
        level.setFriction(false);
        // Only until they meet: afterwards the struck ball runs on towards a cushion (task 3).
        const auto notMetYet = [&level]
        {
            const std::vector<Ball>& balls = level.getBalls();
            return balls[1].velocity == hitbox::Vec2(0.f, 0.f) &&
                   hitbox::length(balls[1].shape.center - balls[0].shape.center) >
                       2.f * radius + 0.01f;
        };
        for (int i = 0; i < 40 && notMetYet(); ++i)
            level.update(hitbox::stepSeconds);
        const std::vector<Ball>& balls = level.getBalls();
        EXPECT_GT(hitbox::dot(balls[1].shape.center - balls[0].shape.center, direction), 0.f)
            << "at " << speed << " px/s the cue ball got past the ball in its way";
        EXPECT_GE(hitbox::length(balls[1].shape.center - balls[0].shape.center),
                  2.f * radius - 0.01f)
            << "at " << speed << " px/s";
    }
}

TEST(Task2ElasticBounce, HiddenBothMovingAlongAVerticalNormalSwapTheirVerticalParts)
{
    // Both balls moving, normal straight up: the vertical parts swap, the horizontal parts
    // stay. A "cue ball stops, other takes its speed" answer ignores the second ball's speed.
    const auto [first, second] =
        PoolLevel::bounceBalls({30.f, 250.f}, {-10.f, -150.f}, {0.f, -1.f});
    EXPECT_NEAR(first.x, 30.f, 1e-4f);
    EXPECT_NEAR(first.y, -150.f, 1e-4f);
    EXPECT_NEAR(second.x, -10.f, 1e-4f);
    EXPECT_NEAR(second.y, 250.f, 1e-4f);
}

TEST(Task2ElasticBounce, HiddenASlantedNormalChangesOnlyThePartAlongIt)
{
    // Normal (0.6, -0.8): closing = dot((-300, 600), n) = -660, so 660 px/s along the
    // normal moves from one ball to the other; a 45-degree answer or a swapped sign misses.
    const auto [first, second] =
        PoolLevel::bounceBalls({-200.f, 500.f}, {100.f, -100.f}, {0.6f, -0.8f});
    EXPECT_NEAR(first.x, 196.f, 1e-3f);
    EXPECT_NEAR(first.y, -28.f, 1e-3f);
    EXPECT_NEAR(second.x, -296.f, 1e-3f);
    EXPECT_NEAR(second.y, 428.f, 1e-3f);
}

TEST(Task2ElasticBounce, HiddenBallsPartingAtAnAngleAreLeftAlone)
{
    // Both moving, parting along a slanted normal (closing = +72): no bounce, bit for bit.
    // Bouncing anyway, or bouncing on the size of the closing speed, turns them round.
    const auto [first, second] = PoolLevel::bounceBalls({150.f, -10.f}, {30.f, 30.f}, {0.8f, 0.6f});
    EXPECT_EQ(first, hitbox::Vec2(150.f, -10.f));
    EXPECT_EQ(second, hitbox::Vec2(30.f, 30.f));
}

TEST(Task2ElasticBounce, HiddenSeededBouncesSwapExactlyTheNormalParts)
{
    // Seeded velocities and normals: after a bounce the part along the normal of each ball is
    // the other's from before, and the part along the surface is its own.
    std::mt19937 random(20240611);
    std::uniform_real_distribution<float> component(-2500.f, 2500.f);
    std::uniform_real_distribution<float> angle(-hitbox::pi, hitbox::pi);
    int bounced = 0;
    for (int bounce = 0; bounce < 150; ++bounce)
    {
        const hitbox::Vec2 first{component(random), component(random)};
        const hitbox::Vec2 second{component(random), component(random)};
        const float direction = angle(random);
        const hitbox::Vec2 normal{std::cos(direction), std::sin(direction)};
        const hitbox::Vec2 surface{-normal.y, normal.x};
        const auto [firstAfter, secondAfter] = PoolLevel::bounceBalls(first, second, normal);
        const bool closing = hitbox::dot(first - second, normal) < 0.f;
        bounced += closing ? 1 : 0;
        const hitbox::Vec2& firstNormalFrom = closing ? second : first;
        const hitbox::Vec2& secondNormalFrom = closing ? first : second;
        ASSERT_NEAR(hitbox::dot(firstAfter, normal), hitbox::dot(firstNormalFrom, normal), 0.02f)
            << "bounce " << bounce;
        ASSERT_NEAR(hitbox::dot(secondAfter, normal), hitbox::dot(secondNormalFrom, normal), 0.02f)
            << "bounce " << bounce;
        ASSERT_NEAR(hitbox::dot(firstAfter, surface), hitbox::dot(first, surface), 0.02f)
            << "bounce " << bounce;
        ASSERT_NEAR(hitbox::dot(secondAfter, surface), hitbox::dot(second, surface), 0.02f)
            << "bounce " << bounce;
    }
    EXPECT_GT(bounced, 30) << "the seed should give plenty of closing pairs";
}

TEST(Task3Cushions, HiddenTheFirstEventOfABallRunningAtTheLeftCushion)
{
    // One ball, so only the cushions can be hit. The left cushion ends at x = 100: the
    // centre touches it at x = 114, after 186 of the 500 px. The normal points into the table.
    PoolLevel level({ballAt({300.f, 400.f}, {-5000.f, 0.f})}, {100.f, 100.f, 800.f, 800.f});
    const BallEvent event = level.findFirstEvent(0.1f);
    ASSERT_TRUE(event.hit);
    EXPECT_EQ(event.first, 0u);
    EXPECT_EQ(event.cushion, 2); // top, bottom, left, right
    EXPECT_NEAR(event.time, 186.f / 500.f, 1e-4f);
    EXPECT_NEAR(event.normal.x, 1.f, 1e-5f);
    EXPECT_NEAR(event.normal.y, 0.f, 1e-5f);
}

TEST(Task3Cushions, HiddenAFastBallBouncesOffTheTopCushionAndStaysOnTheTable)
{
    // Upwards this time, on a wide, short table, from an off-centre start.
    const hitbox::Box table{50.f, 200.f, 1000.f, 600.f};
    for (float speed : {700.f, 30000.f, 90000.f})
    {
        PoolLevel level({ballAt({333.f, 640.f}, {0.f, -speed})}, table);
        level.setFriction(false);
        for (int i = 0; i < 240 && level.getBalls()[0].velocity.y < 0.f; ++i)
        {
            level.update(hitbox::stepSeconds);
            ASSERT_TRUE(hitbox::pointInBox(level.getBalls()[0].shape.center, level.getTable()))
                << "at " << speed;
        }
        const Ball& ball = level.getBalls()[0];
        EXPECT_NEAR(ball.velocity.y, 0.9f * speed, 0.001f * speed) << "90 % restitution";
        EXPECT_NEAR(ball.velocity.x, 0.f, 1e-3f);
        EXPECT_NEAR(ball.shape.center.x, 333.f, 1e-3f);
        EXPECT_GE(ball.shape.center.y, table.top + radius - 0.01f) << "at " << speed;
    }
}

TEST(Task3Cushions, HiddenAnOddlyAimedBallNeverLeavesASmallTable)
{
    // Other angles, speeds and a smaller, off-origin table than the visible test: the centre
    // stays at least a radius inside the cushions.
    const hitbox::Box table{-300.f, 40.f, 500.f, 350.f};
    const hitbox::Box inner = centreBounds(table);
    for (int degrees = 3; degrees < 360; degrees += 29)
        for (float speed : {2500.f, 400000.f})
        {
            const float angle = static_cast<float>(degrees) * hitbox::pi / 180.f;
            PoolLevel level(
                {ballAt({-120.f, 300.f}, {speed * std::cos(angle), speed * std::sin(angle)})},
                table);
            level.setFriction(false);
            for (int i = 0; i < 120; ++i)
            {
                level.update(hitbox::stepSeconds);
                ASSERT_TRUE(hitbox::pointInBox(level.getBalls()[0].shape.center, inner))
                    << degrees << " degrees at " << speed << " px/s, step " << i;
            }
        }
}

TEST(Task3Cushions, HiddenABallTouchingTheBottomCushionBouncesOnlyWhenMovingIntoIt)
{
    // The bottom cushion starts at y = 900; a ball at y = 886 touches it exactly.
    const hitbox::Box table{100.f, 100.f, 800.f, 800.f};
    PoolLevel sliding({ballAt({600.f, 886.f}, {-240.f, 0.f})}, table);
    sliding.setFriction(false);
    for (int i = 0; i < 90; ++i)
        sliding.update(hitbox::stepSeconds);
    EXPECT_EQ(sliding.getBalls()[0].velocity, hitbox::Vec2(-240.f, 0.f))
        << "touching is not a collision: sliding along the cushion, the ball keeps its speed";
    EXPECT_NEAR(sliding.getBalls()[0].shape.center.x, 420.f, 0.01f);

    PoolLevel pushing({ballAt({600.f, 886.f}, {50.f, 400.f})}, table);
    pushing.setFriction(false);
    pushing.update(hitbox::stepSeconds);
    EXPECT_NEAR(pushing.getBalls()[0].velocity.y, -360.f, 0.01f)
        << "moving into the cushion from touching: it bounces at once";
    EXPECT_NEAR(pushing.getBalls()[0].velocity.x, 50.f, 0.01f) << "the part along it is kept";
    EXPECT_LE(pushing.getBalls()[0].shape.center.y, 886.f);
}
