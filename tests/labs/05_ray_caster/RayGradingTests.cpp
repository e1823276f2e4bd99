// Grading tests for lab 5 (ray caster). Each suite checks one task of README.md.
#include "RayLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/geometry/Overlap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{

// Run `steps` fixed steps with the mouse at `mouse` and nothing else pressed.
void runWithMouse(RayLevel& level, hitbox::Vec2 mouse, int steps)
{
    Input input;
    input.setMousePosition(hitbox::toSfml(mouse));
    for (int step = 0; step < steps; ++step)
    {
        level.handleInput(input, hitbox::stepSeconds);
        level.update(hitbox::stepSeconds);
        input.update();
    }
}

// A floor of 40-pixel tiles from x = 0 to 1200 at y = 600, stored left to right.
std::vector<hitbox::Box> tiledFloor()
{
    std::vector<hitbox::Box> tiles;
    for (float x = 0.f; x < 1200.f; x += 40.f)
        tiles.push_back({x, 600.f, 40.f, 40.f});
    return tiles;
}

bool overlapsAnySolid(const RayLevel& level)
{
    for (const hitbox::Box& solid : level.getSolids())
        if (hitbox::boxVsBox(hitbox::toBox(level.getPlayer().getCollisionBox()), solid))
            return true;
    return false;
}

} // namespace

TEST(Task1NearestRayHit, StopsAtTheNearestBoxEvenWhenItIsListedLast)
{
    // Far box first in the list: taking the first hit found would be wrong.
    const RayLevel level({{700.f, 100.f, 50.f, 200.f}, {400.f, 100.f, 50.f, 200.f}},
                         {1000.f, 500.f});
    const RayHit ray = level.castRay({100.f, 200.f}, {1000.f, 200.f});
    ASSERT_TRUE(ray.hit);
    EXPECT_EQ(ray.boxIndex, 1);
    EXPECT_NEAR(ray.end.x, 400.f, 0.01f);
    EXPECT_NEAR(ray.end.y, 200.f, 0.01f);
    EXPECT_EQ(ray.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_NEAR(ray.time, 300.f / 900.f, 1e-4f);
}

TEST(Task1NearestRayHit, NormalPointsBackTowardsTheRayFromEverySide)
{
    const RayLevel level({{500.f, 300.f, 100.f, 100.f}}, {1000.f, 600.f});
    EXPECT_EQ(level.castRay({550.f, 100.f}, {550.f, 500.f}).normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_EQ(level.castRay({550.f, 600.f}, {550.f, 200.f}).normal, hitbox::Vec2(0.f, 1.f));
    EXPECT_EQ(level.castRay({800.f, 350.f}, {300.f, 350.f}).normal, hitbox::Vec2(1.f, 0.f));
}

TEST(Task1NearestRayHit, RayThatMissesEverythingReachesTheMouse)
{
    const RayLevel level({{500.f, 300.f, 100.f, 100.f}}, {1000.f, 600.f});
    const RayHit ray = level.castRay({100.f, 100.f}, {900.f, 100.f});
    EXPECT_FALSE(ray.hit);
    EXPECT_EQ(ray.end, hitbox::Vec2(900.f, 100.f));
    EXPECT_EQ(ray.boxIndex, -1);
}

TEST(Task1NearestRayHit, TheLevelCastsFromThePlayerToTheMouseEveryStep)
{
    // Player 32 x 32 at (100, 184): its centre is (116, 200).
    RayLevel level({{700.f, 100.f, 50.f, 200.f}, {400.f, 150.f, 50.f, 100.f}}, {100.f, 184.f});
    level.setMoveDirection({0.f, 0.f});
    runWithMouse(level, {1000.f, 200.f}, 1);
    ASSERT_TRUE(level.getRay().hit);
    EXPECT_EQ(level.getRay().start, hitbox::Vec2(116.f, 200.f));
    EXPECT_NEAR(level.getRay().end.x, 400.f, 0.01f);
}

TEST(Task2SweepAndSlide, StopsTouchingAWallInsteadOfPassingThrough)
{
    RayLevel level({{500.f, 0.f, 10.f, 675.f}}, {100.f, 300.f});
    level.setMoveDirection({1.f, 0.f});
    runWithMouse(level, {0.f, 0.f}, 240); // 2 s at 300 px/s: far enough to pass the wall
    const hitbox::Box box = hitbox::toBox(level.getPlayer().getCollisionBox());
    EXPECT_NEAR(box.left + box.width, 500.f, 0.01f);
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2SweepAndSlide, SlidesAlongAWallItIsPushedInto)
{
    // One long floor box; moving down-right keeps the sideways part of the speed.
    RayLevel level({{0.f, 600.f, 1200.f, 40.f}}, {100.f, 500.f});
    level.setMoveDirection({1.f, 1.f});
    runWithMouse(level, {0.f, 0.f}, 240);
    const hitbox::Vec2 position = hitbox::toVec2(level.getPlayer().getPosition());
    EXPECT_NEAR(position.y, 568.f, 0.01f) << "resting on the floor";
    const float sidewaysSpeed = 300.f / std::sqrt(2.f);
    EXPECT_NEAR(position.x, 100.f + sidewaysSpeed * 2.f, 1.f) << "never slowed down";
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2SweepAndSlide, TheLabFieldIsNeverEntered)
{
    RayLevel level;
    Input input;
    const std::vector<sf::Keyboard::Key> keys = {sf::Keyboard::Right, sf::Keyboard::Up,
                                                 sf::Keyboard::Left, sf::Keyboard::Down};
    for (int step = 0; step < 120 * 12; ++step)
    {
        // Hold two keys at a time, changing every 0.75 s: diagonal moves into everything.
        const std::size_t phase = static_cast<std::size_t>(step / 90);
        input.setKeyDown(keys[phase % 4]);
        input.setKeyDown(keys[(phase + 1) % 4]);
        level.handleInput(input, hitbox::stepSeconds);
        level.update(hitbox::stepSeconds);
        input.update();
        input.releaseAll();
        ASSERT_FALSE(overlapsAnySolid(level)) << "at step " << step;
    }
}

TEST(Task3TimeOrder, SlidesOverTheSeamsOfATiledFloor)
{
    // x = 1000 is exactly on a seam: both tiles are touched at time 0 (a tie).
    RayLevel level(tiledFloor(), {1000.f, 568.f});
    level.setTimeOrder(true);
    level.setMoveDirection({-1.f, 1.f}); // down-left: pressed into the floor, moving left
    runWithMouse(level, {0.f, 0.f}, 240);
    const float sidewaysSpeed = 300.f / std::sqrt(2.f);
    EXPECT_NEAR(level.getPlayer().getPosition().x, 1000.f - sidewaysSpeed * 2.f, 1.f)
        << "crossed " << int(sidewaysSpeed * 2.f / 40.f) << " seams without slowing down";
    EXPECT_NEAR(level.getPlayer().getPosition().y, 568.f, 0.01f);
    EXPECT_FALSE(level.isStuck());
}

TEST(Task3TimeOrder, TheNearestContactIsHandledFirst)
{
    RayLevel level(tiledFloor(), {1010.f, 568.f});
    level.setTimeOrder(true);
    level.setMoveDirection({-1.f, 1.f}); // the left edge reaches a seam during these steps
    bool sawTwoHits = false;
    for (int step = 0; step < 40; ++step)
    {
        runWithMouse(level, {0.f, 0.f}, 1);
        const std::vector<SolidHit>& hits = level.getLastHits();
        for (std::size_t i = 1; i < hits.size(); ++i)
        {
            sawTwoHits = true;
            EXPECT_LE(hits[i - 1].time, hits[i].time);
        }
    }
    EXPECT_TRUE(sawTwoHits);
}

TEST(Task3TimeOrder, WithoutTimeOrderTheBoxSnagsOnTheFirstSeam)
{
    // The problem the fix solves (seed 004): handling the next tile's corner first stops
    // the player at the seam.
    RayLevel level(tiledFloor(), {1010.f, 568.f});
    level.setTimeOrder(false);
    level.setMoveDirection({-1.f, 1.f});
    runWithMouse(level, {0.f, 0.f}, 240);
    EXPECT_NEAR(level.getPlayer().getPosition().x, 1000.f, 0.01f);
    EXPECT_TRUE(level.isStuck());
}
