// GridRay.h - which tiles does a ray cross? A grid ray cast for line of sight.
//
// Testing a ray against every tile of a map costs one test per tile. On a grid there is no
// need: walk from the ray's start cell to its end cell, one cell at a time, always stepping
// across whichever grid line (vertical or horizontal) the ray reaches next. Only the cells
// the ray passes through are looked at: about columns + rows of them at most (Amanatides and
// Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics 1987; the 2D DDA of
// Ericson, Real-Time Collision Detection, 7.4.2). Units: pixels, y down; the grid's top-left
// corner is at (0, 0) and cell (column, row) covers [column, column + 1) x [row, row + 1)
// times cellSize.
#pragma once

#include "hitbox/geometry/Vec2.h"

#include <vector>

namespace hitbox
{

// A map of square tiles, solid or empty. Plain data: solid[row * columns + column] != 0 is
// a solid tile. A grid whose solid list is not columns * rows long is empty everywhere.
struct TileGrid
{
    int columns = 0;
    int rows = 0;
    float cellSize = 1.f;
    std::vector<unsigned char> solid;
};

// Is the tile at (column, row) solid? Outside the grid: no (empty).
[[nodiscard]] bool isSolidTile(const TileGrid& grid, int column, int row);

// What castRayInGrid found.
struct GridRayResult
{
    bool blocked = false; // the ray passes through the inside of a solid tile
    int column = -1;      // the first such tile (when blocked), else -1
    int row = -1;
    float time = 1.f;     // when the ray enters it: 0 at start, 1 at end
    Vec2 point;           // where it enters: start + time * (end - start)
    Vec2 normal;          // the face it enters by, unit; (0, 0) when it starts in the tile
    int cellsVisited = 0; // tiles the ray passed through, up to and with the blocking one
};

// The ray from `start` to `end` walked through `grid`. EDGE RULE (touching is not colliding):
// a ray is blocked only by a solid tile whose inside it passes through; running exactly along
// a tile's side, through its corner, or reaching it only at `end` is not blocked (so a ray
// along a wall's face sees past it, and one exactly between two diagonal tiles goes through).
// Running along the line between two solid tiles is inside the wall they make: blocked.
// A ray whose first stretch is inside a solid tile (it starts inside, or on its side heading
// in) is blocked at time 0 with normal (0, 0). Entering by a corner: the vertical
// side wins (normal along x), as sweepBoxVsBox. A zero-length ray is blocked only inside a
// solid tile. Outside the grid, and at negative coordinates, everything is empty. A cell size
// of 0, negative or NaN, a grid with no tiles, and NaN, infinity or any coordinate outside
// +-exactRange (Range.h): never blocked, 0 cells visited. Cost: at most columns + rows + 2 steps.
[[nodiscard]] GridRayResult castRayInGrid(const TileGrid& grid, Vec2 start, Vec2 end);

// Line of sight: true when castRayInGrid(grid, from, to) is not blocked (same edge rules).
[[nodiscard]] bool hasLineOfSight(const TileGrid& grid, Vec2 from, Vec2 to);

} // namespace hitbox
