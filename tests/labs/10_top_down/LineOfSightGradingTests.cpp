// Grading tests of lab 10, task 4: line of sight by a grid ray cast (LineOfSight.h). The
// answers are checked against the framework's hitbox::hasLineOfSight, which follows the same
// edge rule (touching is not blocking), on set cases and on many random lines.
#include "LineOfSight.h"
#include "TopDownLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/geometry/GridRay.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <utility>

namespace
{
// A 10 x 10 grid of sightCellSize tiles with the given tiles solid.
hitbox::TileGrid gridWith(std::initializer_list<std::pair<int, int>> solidTiles)
{
    hitbox::TileGrid grid = emptySightGrid({10 * sightCellSize, 10 * sightCellSize});
    for (const auto& [column, row] : solidTiles)
        grid.solid[static_cast<std::size_t>(row * grid.columns + column)] = 1;
    return grid;
}

// A point by tile coordinates (1.5 is the middle of tile 1).
hitbox::Vec2 at(float column, float row)
{
    return {column * sightCellSize, row * sightCellSize};
}
} // namespace

TEST(Task4LineOfSight, AWallBetweenBlocksSight)
{
    const hitbox::TileGrid grid = gridWith({{5, 3}, {5, 4}, {5, 5}});
    EXPECT_FALSE(canSee(grid, at(1.5f, 4.5f), at(8.5f, 4.5f)));
    EXPECT_FALSE(canSee(grid, at(8.5f, 4.5f), at(1.5f, 4.5f))); // both ways
    EXPECT_FALSE(canSee(grid, at(1.5f, 3.2f), at(8.5f, 5.7f))); // slanted
}

TEST(Task4LineOfSight, AnOpenLineAndOneBesideTheWallSee)
{
    const hitbox::TileGrid grid = gridWith({{5, 3}, {5, 4}, {5, 5}});
    EXPECT_TRUE(canSee(grid, at(1.5f, 1.5f), at(8.5f, 1.5f)));
    EXPECT_TRUE(canSee(grid, at(1.5f, 8.5f), at(8.5f, 7.5f)));
}

TEST(Task4LineOfSight, ALineAlongAWallsFaceOnlyTouchesItAndSees)
{
    const hitbox::TileGrid grid = gridWith({{5, 3}, {5, 4}, {5, 5}});
    EXPECT_TRUE(canSee(grid, at(5.f, 0.5f), at(5.f, 9.5f))); // the wall's left face
    EXPECT_TRUE(canSee(grid, at(0.5f, 3.f), at(9.5f, 3.f))); // its top face
}

TEST(Task4LineOfSight, ALineAlongTheSeamInsideAThickWallIsBlocked)
{
    const hitbox::TileGrid grid = gridWith({{4, 3}, {5, 3}, {4, 4}, {5, 4}});
    EXPECT_FALSE(canSee(grid, at(5.f, 0.5f), at(5.f, 9.5f))); // between columns 4 and 5
    EXPECT_FALSE(canSee(grid, at(0.5f, 4.f), at(9.5f, 4.f))); // between rows 3 and 4
}

TEST(Task4LineOfSight, ALineAlongTheSeamIsBlockedFromWhereTheWallBegins)
{
    // A wall one tile thick across the seam: the tiles before it on the line are open, so only
    // the two tiles the line runs between decide.
    EXPECT_FALSE(canSee(gridWith({{4, 4}, {5, 4}}), at(5.f, 0.5f), at(5.f, 9.5f))); // down x = 50
    EXPECT_FALSE(canSee(gridWith({{4, 4}, {5, 4}}), at(5.f, 9.5f), at(5.f, 0.5f))); // up
    EXPECT_FALSE(canSee(gridWith({{4, 4}, {4, 5}}), at(0.5f, 5.f), at(9.5f, 5.f))); // along y = 50
    EXPECT_FALSE(canSee(gridWith({{4, 4}, {4, 5}}), at(9.5f, 5.f), at(0.5f, 5.f))); // leftwards
}

TEST(Task4LineOfSight, APointOnACornerIsInsideTheWallOnlyWhenAllFourTilesAreSolid)
{
    // The corner (5, 5) between tiles (4, 4), (5, 4), (4, 5) and (5, 5): open any one of the
    // four and the point sees itself (it only touches the wall).
    const std::pair<int, int> around[] = {{4, 4}, {5, 4}, {4, 5}, {5, 5}};
    hitbox::TileGrid all = gridWith({});
    for (int column = 3; column <= 6; ++column)
        for (int row = 3; row <= 6; ++row)
            all.solid[static_cast<std::size_t>(row * all.columns + column)] = 1;
    EXPECT_FALSE(canSee(all, at(5.f, 5.f), at(5.f, 5.f)));
    for (const auto& [column, row] : around)
    {
        hitbox::TileGrid grid = all; // the tiles all round solid too, but one of the four open
        grid.solid[static_cast<std::size_t>(row * grid.columns + column)] = 0;
        EXPECT_TRUE(canSee(grid, at(5.f, 5.f), at(5.f, 5.f)))
            << "tile (" << column << ", " << row << ") open";
    }
}

TEST(Task4LineOfSight, AShortLineIntoTheNextTileIsBlockedByIt)
{
    // Lines of a pixel or less that cross one grid line into a wall tile, in each direction.
    const hitbox::TileGrid grid = gridWith({{5, 5}});
    EXPECT_FALSE(canSee(grid, at(4.95f, 5.5f), at(5.05f, 5.5f))); // right, 1 px
    EXPECT_FALSE(canSee(grid, at(6.02f, 5.5f), at(5.98f, 5.5f))); // left, 0.4 px
    EXPECT_FALSE(canSee(grid, at(5.5f, 4.97f), at(5.5f, 5.03f))); // down, 0.6 px
    EXPECT_FALSE(canSee(grid, at(5.5f, 6.05f), at(5.5f, 5.95f))); // up, 1 px
    EXPECT_TRUE(canSee(grid, at(4.9f, 5.5f), at(4.99f, 5.5f)));   // stops short of it
}

TEST(Task4LineOfSight, AWallAtTheFarEndOfTheLongestLineStillBlocks)
{
    // Corner to corner across the whole grid the line crosses 19 tiles; only the last is solid.
    EXPECT_FALSE(canSee(gridWith({{9, 9}}), at(0.1f, 0.2f), at(9.9f, 9.8f)));
    EXPECT_FALSE(canSee(gridWith({{0, 0}}), at(9.9f, 9.8f), at(0.1f, 0.2f)));
    EXPECT_TRUE(canSee(gridWith({{9, 0}}), at(0.1f, 0.2f), at(9.9f, 9.8f)));
}

TEST(Task4LineOfSight, ALineThroughTheCornerBetweenTwoDiagonalTilesSees)
{
    // Tiles (5, 4) and (4, 5) meet only at the corner (5, 5); the diagonal passes through it.
    const hitbox::TileGrid grid = gridWith({{5, 4}, {4, 5}});
    EXPECT_TRUE(canSee(grid, at(2.5f, 2.5f), at(7.5f, 7.5f)));
}

TEST(Task4LineOfSight, FromInsideAWallTileSightIsBlocked)
{
    const hitbox::TileGrid grid = gridWith({{5, 4}});
    EXPECT_FALSE(canSee(grid, at(5.5f, 4.5f), at(8.5f, 8.5f)));
    EXPECT_FALSE(canSee(grid, at(5.5f, 4.5f), at(5.5f, 4.5f))); // from a point to itself
    EXPECT_TRUE(canSee(grid, at(2.5f, 2.5f), at(2.5f, 2.5f)));
}

TEST(Task4LineOfSight, AgreesWithTheFrameworksGridRayCastOnRandomLines)
{
    std::mt19937 random(10);
    std::uniform_real_distribution<float> coordinate(0.f, 10 * sightCellSize);
    std::bernoulli_distribution solid(0.25);
    int blocked = 0;
    for (int map = 0; map < 20; ++map)
    {
        hitbox::TileGrid grid = gridWith({});
        for (unsigned char& tile : grid.solid)
            tile = solid(random) ? 1 : 0;
        for (int line = 0; line < 200; ++line)
        {
            const hitbox::Vec2 from{coordinate(random), coordinate(random)};
            const hitbox::Vec2 to{coordinate(random), coordinate(random)};
            const bool expected = hitbox::hasLineOfSight(grid, from, to);
            blocked += expected ? 0 : 1;
            ASSERT_EQ(canSee(grid, from, to), expected)
                << "from (" << from.x << ", " << from.y << ") to (" << to.x << ", " << to.y << ")";
        }
    }
    EXPECT_GT(blocked, 1000); // most random lines cross a wall: the test is not all "sees"
}

TEST(Task4LineOfSight, AnEnemyBehindAWallDoesNotChase)
{
    // The player is well inside the notice radius, but a wall stands between.
    TopDownLevel level;
    level.clearScene();
    level.addWall({500.f, 200.f, 40.f, 200.f});
    level.placePlayer({600.f, 300.f});
    level.addEnemy({420.f, 300.f});
    hitbox::Input input;
    level.handleInput(input, hitbox::stepSeconds);
    level.update(hitbox::stepSeconds);
    EXPECT_EQ(level.getEnemies().at(0).state, EnemyState::Idle);
}

TEST(Task4LineOfSight, ALineFromFarOutsideTheGridIsBlockedByAWallInIt)
{
    // From 100 000 px to the left the line crosses 10 000 empty tiles' worth of grid lines
    // before it reaches the grid: only the part over the grid may be walked, or the walk
    // gives up before the wall and sees through it.
    const hitbox::TileGrid grid = gridWith({{5, 4}});
    const hitbox::Vec2 farLeft{-100000.f, 4.5f * sightCellSize};
    EXPECT_FALSE(canSee(grid, farLeft, at(5.5f, 4.5f)));
    EXPECT_FALSE(canSee(grid, at(5.5f, 4.5f), farLeft));              // and back out to it
    EXPECT_FALSE(canSee(grid, {-80000.f, -60000.f}, at(5.5f, 4.5f))); // slanted
    const hitbox::Vec2 farBelow{5.5f * sightCellSize, 90000.f};
    EXPECT_FALSE(canSee(grid, farBelow, at(5.5f, 2.5f)));                 // up through the wall
    EXPECT_TRUE(canSee(grid, farBelow, at(6.5f, 2.5f)));                  // beside it: sees
    EXPECT_TRUE(canSee(grid, farLeft, {-50000.f, 4.5f * sightCellSize})); // never over the grid
    EXPECT_EQ(canSee(grid, farLeft, at(9.5f, 3.5f)),
              hitbox::hasLineOfSight(grid, farLeft, at(9.5f, 3.5f)));
}

TEST(Task4LineOfSight, ALineFromFarOutsideAWideOrTallGridIsBlockedWhereItEnters)
{
    // 20 tiles wide and 5 tall, then 5 wide and 20 tall: the grid's width and height differ.
    hitbox::TileGrid wide = emptySightGrid({20 * sightCellSize, 5 * sightCellSize});
    wide.solid[static_cast<std::size_t>(2 * wide.columns + 15)] = 1; // tile (15, 2)
    const float middleOfRow2 = 2.5f * sightCellSize;
    EXPECT_FALSE(canSee(wide, {100000.f, middleOfRow2}, at(5.5f, 2.5f)));   // from the right
    EXPECT_FALSE(canSee(wide, {-100000.f, middleOfRow2}, at(17.5f, 2.5f))); // from the left
    EXPECT_TRUE(canSee(wide, {100000.f, middleOfRow2}, at(16.5f, 2.5f)));   // short of it
    wide.solid[static_cast<std::size_t>(2 * wide.columns + 19)] = 1;        // at the right edge too
    EXPECT_FALSE(canSee(wide, {100000.f, middleOfRow2}, at(19.5f, 2.5f)));

    hitbox::TileGrid tall = emptySightGrid({5 * sightCellSize, 20 * sightCellSize});
    tall.solid[static_cast<std::size_t>(15 * tall.columns + 2)] = 1; // tile (2, 15)
    const float middleOfColumn2 = 2.5f * sightCellSize;
    EXPECT_FALSE(canSee(tall, {middleOfColumn2, 100000.f}, at(2.5f, 5.5f)));   // from below
    EXPECT_FALSE(canSee(tall, {middleOfColumn2, -100000.f}, at(2.5f, 17.5f))); // from above
    EXPECT_TRUE(canSee(tall, {middleOfColumn2, -100000.f}, at(2.5f, 14.5f)));
    tall.solid[0 * 5 + 2] = 1; // tile (2, 0): the first tile the line from above meets
    EXPECT_FALSE(canSee(tall, {middleOfColumn2, -100000.f}, at(2.5f, 0.5f)));
}
