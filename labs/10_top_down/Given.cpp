// Given.cpp - the code given to you in lab 10's line of sight: the grid the walls are marked
// on. Yours is LineOfSight.cpp (canSee). The grading tests build their grids with this file,
// so the grader always uses the course's copy of it: a change here changes nothing there.
#include "LineOfSight.h"

#include <cmath>
#include <cstddef>

hitbox::TileGrid emptySightGrid(hitbox::Vec2 worldSize)
{
    hitbox::TileGrid grid;
    grid.cellSize = sightCellSize;
    grid.columns = static_cast<int>(std::ceil(worldSize.x / sightCellSize));
    grid.rows = static_cast<int>(std::ceil(worldSize.y / sightCellSize));
    grid.solid.assign(static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows),
                      0);
    return grid;
}

void markWall(hitbox::TileGrid& grid, const hitbox::Box& wall)
{
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column)
        {
            const hitbox::Vec2 centre{(column + 0.5f) * grid.cellSize,
                                      (row + 0.5f) * grid.cellSize};
            if (centre.x > wall.left && centre.x < wall.left + wall.width && centre.y > wall.top &&
                centre.y < wall.top + wall.height)
                grid.solid[static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.columns) +
                           static_cast<std::size_t>(column)] = 1;
        }
}
