// BallOrder.h - data locality (Nystrom, Game Programming Patterns, "Data Locality"): balls that
// are near each other in the arena are stored near each other in memory.
//
// The broadphase hands the pair loop pairs of neighbours. If ball 17 sits next to ball 83,512,
// nearly every pair makes the processor fetch a ball from main memory, and the loop spends
// most of its time waiting. Sorted into strips, a pair's balls and the next pair's are mostly
// in the cache already. Lab 8 sorts each new crowd once, as a game does while loading a level.
// The balls mix again as they wander: steps take about 0.9 x the CPU time at 100,000 balls at
// first, and most of that gain is gone after a minute or so (docs/performance.md, eighth round).
#pragma once

#include "Ball.h"

#include "hitbox/geometry/Shapes.h"

#include <vector>

// Sorts `balls` by strip (rows `tileSize` tall, top to bottom), then by tile along the strip
// (left to right); balls in one tile keep their order (a stable counting sort: one pass to
// count, one to move). A ball outside `area` counts as in the nearest edge tile, a NaN
// coordinate as in the first column or row. tileSize <= 0 or NaN: tiles as wide as `area`.
// Tiles grow where `area` would need more than about 65,536 of them (or a row or column of
// more). An `area` that is not finite: the balls keep their order.
void sortBallsByTile(std::vector<Ball>& balls, hitbox::Box area, float tileSize);
