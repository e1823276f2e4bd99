// GridRayTest.cpp - the grid ray cast (GridRay.h): one test per edge rule.
#include "hitbox/geometry/GridRay.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

using hitbox::castRayInGrid;
using hitbox::GridRayResult;
using hitbox::hasLineOfSight;
using hitbox::TileGrid;
using hitbox::Vec2;

namespace
{
// A grid of 10 px tiles from a picture: '#' solid, '.' empty, one string a row.
TileGrid gridOf(std::initializer_list<std::string> rows, float cellSize = 10.f)
{
    TileGrid grid;
    grid.cellSize = cellSize;
    grid.rows = static_cast<int>(rows.size());
    for (const std::string& row : rows)
    {
        grid.columns = static_cast<int>(row.size());
        for (const char tile : row)
            grid.solid.push_back(tile == '#' ? 1 : 0);
    }
    return grid;
}

// 5 x 5 tiles; one solid tile at column 3, row 2 (x 30..40, y 20..30).
const TileGrid oneWall = gridOf({".....", ".....", "...#.", ".....", "....."});
} // namespace

TEST(GridRay, ARayStopsAtTheFirstSolidTile)
{
    // Along row 2 from x = 5 to x = 48: enters the wall at x = 30.
    const GridRayResult result = castRayInGrid(oneWall, {5.f, 25.f}, {45.f, 25.f});
    ASSERT_TRUE(result.blocked);
    EXPECT_EQ(result.column, 3);
    EXPECT_EQ(result.row, 2);
    EXPECT_FLOAT_EQ(result.time, 25.f / 40.f);
    EXPECT_FLOAT_EQ(result.point.x, 30.f);
    EXPECT_FLOAT_EQ(result.point.y, 25.f);
    EXPECT_FLOAT_EQ(result.normal.x, -1.f);
    EXPECT_FLOAT_EQ(result.normal.y, 0.f);
    EXPECT_EQ(result.cellsVisited, 4); // columns 0, 1, 2 and the wall
}

TEST(GridRay, EachWayGivesTheFaceItEntersBy)
{
    EXPECT_FLOAT_EQ(castRayInGrid(oneWall, {45.f, 25.f}, {5.f, 25.f}).normal.x, 1.f);
    EXPECT_FLOAT_EQ(castRayInGrid(oneWall, {35.f, 5.f}, {35.f, 45.f}).normal.y, -1.f);
    EXPECT_FLOAT_EQ(castRayInGrid(oneWall, {35.f, 45.f}, {35.f, 5.f}).normal.y, 1.f);
}

TEST(GridRay, ADiagonalRayVisitsOnlyTheTilesItCrosses)
{
    // From (1, 2) to (49, 47): a slanted ray across the empty 5 x 5 grid, clear of the wall.
    const TileGrid empty = gridOf({".....", ".....", ".....", ".....", "....."});
    const GridRayResult result = castRayInGrid(empty, {1.f, 2.f}, {49.f, 47.f});
    EXPECT_FALSE(result.blocked);
    // It crosses 4 vertical and 4 horizontal lines, never at a corner: 9 tiles.
    EXPECT_EQ(result.cellsVisited, 9);
    EXPECT_TRUE(castRayInGrid(oneWall, {1.f, 2.f}, {49.f, 47.f}).blocked);
}

TEST(GridRay, LineOfSightIsTheOppositeOfBlocked)
{
    EXPECT_FALSE(hasLineOfSight(oneWall, {5.f, 25.f}, {45.f, 25.f}));
    EXPECT_TRUE(hasLineOfSight(oneWall, {5.f, 5.f}, {45.f, 5.f}));
    EXPECT_TRUE(hasLineOfSight(oneWall, {5.f, 25.f}, {25.f, 25.f}));
}

// Edge rule: touching is not colliding.
TEST(GridRay, RunningAlongATilesSideIsNotBlocked)
{
    EXPECT_FALSE(castRayInGrid(oneWall, {5.f, 20.f}, {45.f, 20.f}).blocked);  // its top
    EXPECT_FALSE(castRayInGrid(oneWall, {5.f, 30.f}, {45.f, 30.f}).blocked);  // its bottom
    EXPECT_FALSE(castRayInGrid(oneWall, {30.f, 5.f}, {30.f, 45.f}).blocked);  // its left
    EXPECT_FALSE(castRayInGrid(oneWall, {40.f, 45.f}, {40.f, 5.f}).blocked);  // its right
    EXPECT_TRUE(castRayInGrid(oneWall, {5.f, 20.5f}, {45.f, 20.5f}).blocked); // just inside
}

TEST(GridRay, RunningAlongTheLineBetweenTwoSolidTilesIsBlocked)
{
    // A wall two tiles thick: the line between its tiles is inside the wall.
    TileGrid thick = oneWall;
    thick.solid[2 * 5 + 2] = 1; // tile (2, 2) beside the wall's tile (3, 2)
    const GridRayResult result = castRayInGrid(thick, {30.f, 5.f}, {30.f, 45.f});
    EXPECT_TRUE(result.blocked);
    EXPECT_FLOAT_EQ(result.point.y, 20.f);
    EXPECT_FLOAT_EQ(result.normal.y, -1.f);
    EXPECT_FALSE(castRayInGrid(oneWall, {30.f, 5.f}, {30.f, 45.f}).blocked); // one side only
}

TEST(GridRay, PassingExactlyThroughACornerIsNotBlocked)
{
    // Two solid tiles touching at a corner, (20, 20): the diagonal between them goes through.
    const TileGrid diagonal = gridOf({".....", ".#...", "..#..", ".....", "....."});
    EXPECT_FALSE(castRayInGrid(diagonal, {5.f, 35.f}, {35.f, 5.f}).blocked);
    // The other diagonal runs through both tiles' insides.
    const GridRayResult result = castRayInGrid(diagonal, {5.f, 5.f}, {45.f, 45.f});
    ASSERT_TRUE(result.blocked);
    EXPECT_EQ(result.column, 1);
    EXPECT_EQ(result.row, 1);
    // Entering by the corner (10, 10): the vertical side wins.
    EXPECT_FLOAT_EQ(result.normal.x, -1.f);
    EXPECT_FLOAT_EQ(result.normal.y, 0.f);
}

TEST(GridRay, ReachingATileOnlyAtTheEndIsNotBlocked)
{
    EXPECT_FALSE(castRayInGrid(oneWall, {5.f, 25.f}, {30.f, 25.f}).blocked);
    EXPECT_TRUE(castRayInGrid(oneWall, {5.f, 25.f}, {30.5f, 25.f}).blocked);
}

TEST(GridRay, StartingInASolidTileIsBlockedAtTimeZero)
{
    const GridRayResult inside = castRayInGrid(oneWall, {35.f, 25.f}, {5.f, 25.f});
    ASSERT_TRUE(inside.blocked);
    EXPECT_FLOAT_EQ(inside.time, 0.f);
    EXPECT_FLOAT_EQ(inside.normal.x, 0.f);
    EXPECT_FLOAT_EQ(inside.normal.y, 0.f);
    // On its side, heading in: also time 0. Heading out: not blocked.
    EXPECT_FLOAT_EQ(castRayInGrid(oneWall, {30.f, 25.f}, {45.f, 25.f}).time, 0.f);
    EXPECT_TRUE(castRayInGrid(oneWall, {30.f, 25.f}, {45.f, 25.f}).blocked);
    EXPECT_FALSE(castRayInGrid(oneWall, {30.f, 25.f}, {5.f, 25.f}).blocked);
}

TEST(GridRay, AZeroLengthRayIsBlockedOnlyInsideASolidTile)
{
    EXPECT_TRUE(castRayInGrid(oneWall, {35.f, 25.f}, {35.f, 25.f}).blocked);
    EXPECT_FALSE(castRayInGrid(oneWall, {30.f, 25.f}, {30.f, 25.f}).blocked); // on its side
    EXPECT_FALSE(castRayInGrid(oneWall, {5.f, 5.f}, {5.f, 5.f}).blocked);
    EXPECT_EQ(castRayInGrid(oneWall, {5.f, 5.f}, {5.f, 5.f}).cellsVisited, 1);
}

TEST(GridRay, OutsideTheGridAndNegativeCoordinatesAreEmpty)
{
    EXPECT_FALSE(castRayInGrid(oneWall, {-50.f, -5.f}, {100.f, -5.f}).blocked);
    EXPECT_EQ(castRayInGrid(oneWall, {-50.f, -5.f}, {100.f, -5.f}).cellsVisited, 0);
    // From far outside, through the wall: the walk starts where the ray enters the grid.
    const GridRayResult result = castRayInGrid(oneWall, {-95.f, 25.f}, {105.f, 25.f});
    ASSERT_TRUE(result.blocked);
    EXPECT_FLOAT_EQ(result.point.x, 30.f);
    EXPECT_EQ(result.cellsVisited, 4);
    EXPECT_FALSE(hitbox::isSolidTile(oneWall, -1, 2));
    EXPECT_FALSE(hitbox::isSolidTile(oneWall, 5, 2));
    EXPECT_TRUE(hitbox::isSolidTile(oneWall, 3, 2));
}

TEST(GridRay, AnUnusableGridIsNeverBlocked)
{
    TileGrid zeroSize = oneWall;
    zeroSize.cellSize = 0.f;
    EXPECT_FALSE(castRayInGrid(zeroSize, {5.f, 25.f}, {45.f, 25.f}).blocked);
    TileGrid negative = oneWall;
    negative.cellSize = -10.f;
    EXPECT_FALSE(castRayInGrid(negative, {-5.f, -25.f}, {-45.f, -25.f}).blocked);
    TileGrid wrongList = oneWall;
    wrongList.solid.pop_back();
    EXPECT_FALSE(castRayInGrid(wrongList, {5.f, 25.f}, {45.f, 25.f}).blocked);
    EXPECT_FALSE(castRayInGrid(TileGrid{}, {5.f, 25.f}, {45.f, 25.f}).blocked);
}

TEST(GridRay, NaNAndInfinityAreNeverBlocked)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_FALSE(castRayInGrid(oneWall, {nan, 25.f}, {45.f, 25.f}).blocked);
    EXPECT_FALSE(castRayInGrid(oneWall, {5.f, 25.f}, {inf, 25.f}).blocked);
    TileGrid nanSize = oneWall;
    nanSize.cellSize = nan;
    EXPECT_FALSE(castRayInGrid(nanSize, {5.f, 25.f}, {45.f, 25.f}).blocked);
    EXPECT_EQ(castRayInGrid(oneWall, {nan, 25.f}, {45.f, 25.f}).cellsVisited, 0);
}

TEST(GridRay, AHugeRayStepsOnlyThroughTheGrid)
{
    // 1e6 px each way, 1000 x 1 tiles of 1 px: one step a tile crossed, none outside.
    TileGrid strip;
    strip.columns = 1000;
    strip.rows = 1;
    strip.solid.assign(1000, 0);
    const GridRayResult clear = castRayInGrid(strip, {-1e6f, 0.5f}, {1e6f, 0.5f});
    EXPECT_FALSE(clear.blocked);
    EXPECT_EQ(clear.cellsVisited, 1000);
    strip.solid[999] = 1;
    const GridRayResult last = castRayInGrid(strip, {-1e6f, 0.5f}, {1e6f, 0.5f});
    ASSERT_TRUE(last.blocked);
    EXPECT_EQ(last.column, 999);
    EXPECT_FLOAT_EQ(last.point.x, 999.f);
    // Beyond the range: no answer but "not blocked".
    EXPECT_FALSE(castRayInGrid(strip, {-2e6f, 0.5f}, {2e6f, 0.5f}).blocked);
}
