// Grading tests for lab 5 (ray caster). Each suite checks one task of README.md.
#include "labs/05_ray_caster/RayChecks.h"

#include "RayLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{

using namespace raychecks;

// A floor of 40-pixel tiles from x = 0 to 1200 at y = 600, stored left to right.
std::vector<hitbox::Box> tiledFloor()
{
    return tileLine({0.f, 600.f}, {40.f, 0.f}, 30);
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
    // Player 32 x 32 at (0, 0): its centre is (16, 16). Standing still at the origin, so the
    // step's move (task 2) cannot take it anywhere, even one that adds where it stands.
    RayLevel level({{700.f, 0.f, 50.f, 200.f}, {400.f, 0.f, 50.f, 100.f}}, {0.f, 0.f});
    level.setMoveDirection({0.f, 0.f});
    runWithMouse(level, {1000.f, 16.f}, 1);
    ASSERT_TRUE(level.getRay().hit);
    EXPECT_EQ(level.getRay().start, hitbox::Vec2(16.f, 16.f));
    EXPECT_NEAR(level.getRay().end.x, 400.f, 0.01f);
}

TEST(Task2MoveAndSlide, StopsTouchingAWallInsteadOfPassingThrough)
{
    RayLevel level({{500.f, 0.f, 10.f, 675.f}}, {100.f, 300.f});
    level.setMoveDirection({1.f, 0.f});
    runWithMouse(level, {0.f, 0.f}, 240); // 2 s at 300 px/s: far enough to pass the wall
    const hitbox::Box box = hitbox::toBox(level.getPlayer().getCollisionBox());
    EXPECT_NEAR(box.left + box.width, 500.f, 0.01f);
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2MoveAndSlide, SlidesAlongAWallItIsPushedInto)
{
    // One long floor box; moving down-right keeps the sideways part of the speed.
    RayLevel level({{0.f, 600.f, 1200.f, 40.f}}, {100.f, 500.f});
    level.setMoveDirection({1.f, 1.f});
    runWithMouse(level, {0.f, 0.f}, 240);
    const hitbox::Vec2 position = hitbox::toVec2(level.getPlayer().getPosition());
    EXPECT_NEAR(position.y, 568.f, 0.01f) << "resting on the floor";
    EXPECT_NEAR(position.x, 100.f + diagonalSpeed * 2.f, 1.f) << "never slowed down";
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2MoveAndSlide, TheLabFieldIsNeverEntered)
{
    RayLevel level;
    hitbox::Input input;
    const std::vector<sf::Keyboard::Key> keys = {sf::Keyboard::Key::Right, sf::Keyboard::Key::Up,
                                                 sf::Keyboard::Key::Left, sf::Keyboard::Key::Down};
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

TEST(Task2MoveAndSlide, SlidesOverTheSeamsOfATiledFloor)
{
    // x = 1000 is exactly on a seam: both tiles are touched at time 0 (a tie).
    RayLevel level(tiledFloor(), {1000.f, 568.f});
    level.setTimeOrder(true);
    level.setMoveDirection({-1.f, 1.f}); // down-left: pressed into the floor, moving left
    runWithMouse(level, {0.f, 0.f}, 240);
    EXPECT_NEAR(level.getPlayer().getPosition().x, 1000.f - diagonalSpeed * 2.f, 1.f)
        << "crossed " << int(diagonalSpeed * 2.f / 40.f) << " seams without slowing down";
    EXPECT_NEAR(level.getPlayer().getPosition().y, 568.f, 0.01f);
    // (Whether the level calls that stuck is task 3's isSnagged: Task3Stuck tests it, so a
    // mistake there costs task 3 only.)
}

TEST(Task2MoveAndSlide, TheHitsAreKeptNearestFirst)
{
    // Into a corner in one step: the wall (0.5 px away) is reached before the floor (1.5 px
    // away), though the floor comes first in the list.
    RayLevel level({{0.f, 600.f, 1200.f, 40.f}, {0.f, 0.f, 100.f, 700.f}}, {100.5f, 566.5f});
    level.setTimeOrder(true);
    level.setMoveDirection({-1.f, 1.f});
    runWithMouse(level, {0.f, 0.f}, 1);
    const std::vector<hitbox::Hit>& hits = level.getLastHits();
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].normal, hitbox::Vec2(1.f, 0.f)) << "the wall first";
    EXPECT_EQ(hits[1].normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_LE(hits[0].time, hits[1].time);
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2MoveAndSlide, WithoutTimeOrderTheBoxSnagsOnTheFirstSeam)
{
    // The problem the time order solves (javidx9, "Arbitrary Rectangle Collision Detection &
    // Resolution"): handling the next tile's corner first stops the player at the seam.
    RayLevel level(tiledFloor(), {1010.f, 568.f});
    level.setTimeOrder(false);
    level.setMoveDirection({-1.f, 1.f});
    runWithMouse(level, {0.f, 0.f}, 240);
    EXPECT_NEAR(level.getPlayer().getPosition().x, 1000.f, 0.01f);
}

TEST(Task3Stuck, AStepThatHardlyMovesIsStuck)
{
    EXPECT_TRUE(isSnagged({1.77f, 1.77f}, {0.f, 0.f}));  // pressed into a corner
    EXPECT_TRUE(isSnagged({1.77f, 1.77f}, {0.2f, 0.f})); // a tenth of the way is not moving
    EXPECT_TRUE(isSnagged({-2.5f, 0.f}, {0.f, -0.24f})); // any direction
}

TEST(Task3Stuck, SlidingIsNotStuck)
{
    // Pressed diagonally into a floor: only the sideways part moves, and that is moving.
    EXPECT_FALSE(isSnagged({-1.77f, 1.77f}, {-1.77f, 0.f}));
    EXPECT_FALSE(isSnagged({2.5f, 0.f}, {0.26f, 0.f}));
}

TEST(Task3Stuck, NotWantingToMoveIsNeverStuck)
{
    EXPECT_FALSE(isSnagged({0.f, 0.f}, {0.f, 0.f}));
}

TEST(Task3Stuck, ExactlyATenthOfTheWayIsNotStuckJustUnderIs)
{
    // The edge of the rule: "less than a tenth" is stuck, a tenth itself is not.
    EXPECT_FALSE(isSnagged({4.f, 0.f}, {0.4f, 0.f}));
    EXPECT_FALSE(isSnagged({0.f, -4.f}, {0.f, -0.4f}));
    EXPECT_TRUE(isSnagged({4.f, 0.f}, {0.39f, 0.f}));
    EXPECT_FALSE(isSnagged({10.f, 0.f}, {1.f, 0.f})) << "1 px of 10 is a tenth: not stuck";
}

TEST(Task3Stuck, ATinyWantedMoveThatIsBlockedIsStuckToo)
{
    // Half a pixel wanted, nothing moved: stuck, however small the step.
    EXPECT_TRUE(isSnagged({0.5f, 0.f}, {0.f, 0.f}));
}
