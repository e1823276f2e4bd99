// LineOfSight.h - can an enemy see the player? A grid ray cast through the walls' tiles.
//
// The walls are marked on a grid of small square tiles (sightCellSize pixels); sight from one
// point to another is blocked when the straight line between them passes through the inside
// of a wall tile. Walking the line one tile at a time, always across whichever grid line it
// reaches next, looks only at the tiles the line crosses (Amanatides and Woo, "A Fast Voxel
// Traversal Algorithm for Ray Tracing", 1987; the framework's hitbox::castRayInGrid).
#pragma once

#include "hitbox/geometry/GridRay.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Vec2.h"

// The tiles the walls are marked on, in pixels: the walls' sides are multiples of it.
constexpr float sightCellSize = 10.f;

// Given (Given.cpp): an empty grid of sightCellSize tiles covering `worldSize` pixels.
[[nodiscard]] hitbox::TileGrid emptySightGrid(hitbox::Vec2 worldSize);
// Given: marks solid every tile whose centre is inside `wall` (tiles outside the grid are
// left out).
void markWall(hitbox::TileGrid& grid, const hitbox::Box& wall);

// Task 4: true when the line from `from` to `to` passes through the inside of no solid tile.
// Edge rule, as everywhere: touching is not blocking. A line exactly along a tile's side, or
// through the corner between two diagonal tiles, sees past them; a line that starts inside a
// solid tile is blocked, and so is one along the line between two solid tiles (inside the
// wall they make). From a point to itself: blocked only inside a solid tile.
[[nodiscard]] bool canSee(const hitbox::TileGrid& grid, hitbox::Vec2 from, hitbox::Vec2 to);
