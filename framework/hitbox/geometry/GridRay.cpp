#include "hitbox/geometry/GridRay.h"

#include "hitbox/geometry/Range.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace hitbox
{

namespace
{
const double never = std::numeric_limits<double>::infinity();

bool isUsable(const TileGrid& grid)
{
    return grid.columns > 0 && grid.rows > 0 && grid.cellSize > 0.f &&
           withinExactRange(grid.cellSize) &&
           grid.solid.size() ==
               static_cast<std::size_t>(grid.columns) * static_cast<std::size_t>(grid.rows);
}

// The cell index of a coordinate, as an int even far outside the grid (-1 or count there).
int cellIndex(double value, double size, int count)
{
    const double index = std::floor(value / size);
    if (index < 0.0)
        return -1;
    return index >= count ? count : static_cast<int>(index);
}

// The part [enter, leave] of the ray's times 0..1 that is within 0..size on one axis.
void clipAxis(double from, double move, double size, double& enter, double& leave, bool& byThis)
{
    if (move == 0.0)
    {
        if (from < 0.0 || from > size)
            leave = -1.0; // beside the grid all along
        return;
    }
    double near = (0.0 - from) / move;
    double far = (size - from) / move;
    if (near > far)
        std::swap(near, far);
    if (near > enter)
    {
        enter = near;
        byThis = true;
    }
    leave = std::min(leave, far);
}
} // namespace

bool isSolidTile(const TileGrid& grid, int column, int row)
{
    if (!isUsable(grid) || column < 0 || row < 0 || column >= grid.columns || row >= grid.rows)
        return false;
    return grid.solid[static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.columns) +
                      static_cast<std::size_t>(column)] != 0;
}

GridRayResult castRayInGrid(const TileGrid& grid, Vec2 start, Vec2 end)
{
    GridRayResult result;
    if (!isUsable(grid) || !withinExactRange(start) || !withinExactRange(end))
        return result;
    const double size = grid.cellSize;
    const double x0 = start.x, y0 = start.y;
    const double dx = double(end.x) - x0, dy = double(end.y) - y0;
    // A ray running exactly along a grid line only touches the tiles on either side: it is
    // inside a wall only where the tiles on both sides are solid.
    const bool alongX = dx == 0.0 && std::fmod(x0, size) == 0.0;
    const bool alongY = dy == 0.0 && std::fmod(y0, size) == 0.0;
    // Only the stretch of the ray inside the grid is walked (so at most columns + rows steps).
    double t = 0.0;
    double tEnd = 1.0;
    bool enteredByX = false;
    bool enteredByY = false;
    clipAxis(x0, dx, size * grid.columns, t, tEnd, enteredByX);
    clipAxis(y0, dy, size * grid.rows, t, tEnd, enteredByY);
    if (dx == 0.0 && dy == 0.0 && tEnd >= 0.0)
        tEnd = 0.5; // a point in the grid: test the tile it is in (its stretch is itself)
    const int stepX = dx > 0.0 ? 1 : -1;
    const int stepY = dy > 0.0 ? 1 : -1;
    // The next grid line each way, as a line number: strictly ahead of where the walk starts.
    const double xStart = x0 + dx * t, yStart = y0 + dy * t;
    double lineX = dx > 0.0 ? std::floor(xStart / size) + 1.0 : std::ceil(xStart / size) - 1.0;
    double lineY = dy > 0.0 ? std::floor(yStart / size) + 1.0 : std::ceil(yStart / size) - 1.0;
    bool byX = enteredByX; // ties (a corner): the vertical side wins
    const int maxSteps = grid.columns + grid.rows + 4;
    // [slide:grid-ray-walk]
    // Step to whichever grid line comes first: tx (the next vertical one) or ty.
    for (int step = 0; t < tEnd && step < maxSteps; ++step)
    {
        const double tx = dx != 0.0 ? (lineX * size - x0) / dx : never;
        const double ty = dy != 0.0 ? (lineY * size - y0) / dy : never;
        const double tNext = std::min({tx, ty, tEnd});
        if (tNext > t)
        {
            // The middle of this stretch is inside exactly one tile: the one the ray crosses.
            const double middle = dx == 0.0 && dy == 0.0 ? 0.0 : (t + tNext) / 2.0;
            const int column = cellIndex(x0 + dx * middle, size, grid.columns);
            const int row = cellIndex(y0 + dy * middle, size, grid.rows);
            if (column >= 0 && row >= 0 && column < grid.columns && row < grid.rows)
                ++result.cellsVisited;
            // Along a grid line the tile found is the one after the line; the one before it
            // must be solid too (and all four round a grid corner, for a point on one).
            const bool inside = isSolidTile(grid, column, row) &&
                                (!alongX || isSolidTile(grid, column - 1, row)) &&
                                (!alongY || isSolidTile(grid, column, row - 1)) &&
                                (!(alongX && alongY) || isSolidTile(grid, column - 1, row - 1));
            if (inside)
            {
                result.blocked = true;
                result.column = column;
                result.row = row;
                result.time = static_cast<float>(t);
                result.point = {static_cast<float>(x0 + dx * t), static_cast<float>(y0 + dy * t)};
                if (t > 0.0)
                    result.normal = byX ? Vec2{float(-stepX), 0.f} : Vec2{0.f, float(-stepY)};
                return result;
            }
        }
        byX = tx <= tNext;
        if (tx <= tNext)
            lineX += stepX;
        if (ty <= tNext)
            lineY += stepY;
        t = tNext;
    }
    // [/slide]
    return result;
}

bool hasLineOfSight(const TileGrid& grid, Vec2 from, Vec2 to)
{
    return !castRayInGrid(grid, from, to).blocked;
}

} // namespace hitbox
