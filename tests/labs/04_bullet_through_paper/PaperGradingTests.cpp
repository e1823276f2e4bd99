// Grading tests for lab 4 (bullet through paper). Each suite checks one task of README.md.
#include "PaperLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Tunnelling.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{

// Fire one shot and run until both bullets are done (stopped or gone), at most 10 s.
PaperLevel shootOnce(float speed)
{
    PaperLevel level;
    level.setAutoFire(false);
    level.fire(speed);
    for (int step = 0; step < 1200; ++step)
    {
        level.update(hitbox::stepSeconds);
        if (!level.getBullet(Lane::Discrete)->isFlying() &&
            !level.getBullet(Lane::Swept)->isFlying())
            break;
    }
    return level;
}

const std::vector<float> risingSpeeds = {300.f,  600.f,   1500.f,   1920.f,   2500.f,
                                         7000.f, 33333.f, 100000.f, 456789.f, 1000000.f};

} // namespace

TEST(Task1DiscreteTest, SlowBulletStopsInsideTheWall)
{
    const PaperLevel level = shootOnce(600.f);
    const Bullet& bullet = *level.getBullet(Lane::Discrete);
    EXPECT_TRUE(bullet.hitTheWall());
    EXPECT_TRUE(hitbox::boxVsBox(hitbox::toBox(bullet.getCollisionBox()), level.getWall()))
        << "a discrete test finds the wall only once the bullet is already inside it";
    EXPECT_EQ(level.getScore(Lane::Discrete).hits, 1);
    EXPECT_EQ(level.getScore(Lane::Discrete).misses, 0);
}

TEST(Task1DiscreteTest, EveryShotSlowerThanBulletPlusWallPerStepHits)
{
    // 12 px bullet + 4 px wall: any step shorter than 16 px must land inside the wall once.
    for (float speed : {120.f, 600.f, 1000.f, 1500.f, 1900.f})
    {
        const PaperLevel level = shootOnce(speed);
        EXPECT_EQ(level.getScore(Lane::Discrete).hits, 1) << "at " << speed << " px/s";
    }
}

TEST(Task1DiscreteTest, VeryFastBulletPassesThroughUnseen)
{
    // Not a bug in your code: this is the problem the lab is about.
    const PaperLevel level = shootOnce(100000.f);
    EXPECT_EQ(level.getScore(Lane::Discrete).misses, 1);
}

TEST(Task2SweptTest, BulletAtAnySpeedStopsExactlyTouchingTheWall)
{
    for (float speed : risingSpeeds)
    {
        const PaperLevel level = shootOnce(speed);
        const Bullet& bullet = *level.getBullet(Lane::Swept);
        EXPECT_TRUE(bullet.hitTheWall()) << "at " << speed << " px/s";
        const hitbox::Box stopped = hitbox::toBox(bullet.getCollisionBox());
        EXPECT_NEAR(stopped.left + stopped.width, level.getWall().left, 0.01f) << "at " << speed;
        EXPECT_EQ(level.getScore(Lane::Swept).misses, 0) << "at " << speed << " px/s";
    }
}

TEST(Task2SweptTest, NeverMissesWhileTheDiscreteLaneDoes)
{
    PaperLevel level; // auto-fire: faster and faster shots
    hitbox::simulate(level, 120 * 40);
    EXPECT_GE(level.getScore(Lane::Swept).hits, 10);
    EXPECT_EQ(level.getScore(Lane::Swept).misses, 0);
    EXPECT_GT(level.getScore(Lane::Discrete).misses, 0);
}

TEST(Task3TunnelWarning, ShortStepsCannotTunnel)
{
    PaperLevel level;
    level.setAutoFire(false);
    level.fire(600.f);
    const Bullet& bullet = *level.getBullet(Lane::Discrete);
    EXPECT_FALSE(level.stepCouldTunnel(bullet, {5.f, 0.f}));
    EXPECT_FALSE(level.stepCouldTunnel(bullet, {15.9f, 0.f}));
    EXPECT_FALSE(level.stepCouldTunnel(bullet, {-15.9f, 0.f}));
    EXPECT_FALSE(level.stepCouldTunnel(bullet, {0.f, 0.f}));
}

TEST(Task3TunnelWarning, StepsAsLongAsBulletPlusWallCanTunnel)
{
    PaperLevel level;
    level.setAutoFire(false);
    level.fire(600.f);
    const Bullet& bullet = *level.getBullet(Lane::Discrete);
    EXPECT_TRUE(level.stepCouldTunnel(bullet, {16.f, 0.f}));
    EXPECT_TRUE(level.stepCouldTunnel(bullet, {40.f, 0.f}));
    EXPECT_TRUE(level.stepCouldTunnel(bullet, {-40.f, 0.f}));
    // Up or down, the wall is 480 px tall: the bullet (6 px) cannot jump over it that way
    // unless the step is longer than 486 px.
    EXPECT_FALSE(level.stepCouldTunnel(bullet, {0.f, 400.f}));
    EXPECT_TRUE(level.stepCouldTunnel(bullet, {0.f, 500.f}));
    EXPECT_TRUE(level.stepCouldTunnel(bullet, {0.f, -500.f})) << "upwards too";
    EXPECT_TRUE(level.stepCouldTunnel(bullet, {0.f, 486.f})) << "exactly bullet + wall: can tunnel";
}

TEST(Task3TunnelWarning, FastShotShowsTheWarningSlowShotDoesNot)
{
    PaperLevel level;
    level.setAutoFire(false);
    level.fire(100000.f);
    level.update(hitbox::stepSeconds);
    EXPECT_TRUE(level.getBullet(Lane::Discrete)->couldTunnel());
    EXPECT_TRUE(level.getBullet(Lane::Swept)->couldTunnel());

    level.fire(600.f);
    level.update(hitbox::stepSeconds);
    EXPECT_FALSE(level.getBullet(Lane::Discrete)->couldTunnel());
}

TEST(Task3TunnelWarning, AgreesWithTheFrameworkForStepsThatReachTheWall)
{
    PaperLevel level;
    level.setAutoFire(false);
    level.fire(600.f);
    const Bullet& bullet = *level.getBullet(Lane::Discrete);
    const float distance =
        level.getWall().left - (hitbox::toBox(bullet.getCollisionBox()).left + 12.f);
    for (float extra = 0.5f; extra < 200.f; extra += 0.5f)
    {
        const sf::Vector2f step{distance + extra, 0.f}; // always reaches into the wall
        // ASSERT: the first step length that disagrees is enough (not hundreds like it).
        ASSERT_EQ(level.stepCouldTunnel(bullet, step),
                  hitbox::canTunnel(hitbox::toBox(bullet.getCollisionBox()), hitbox::toVec2(step),
                                    level.getWall()))
            << "step " << step.x << " px (the first step length that disagrees)";
    }
}
