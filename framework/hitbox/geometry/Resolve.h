// Resolve.h - move a box through a world of solid boxes for one step, sliding along them.
//
// One moving box, many still ones (tiles, walls, platforms). Two ways to do it:
//   - moveBoxAndSlide (javidx9, "Arbitrary Rectangle Collision Detection & Resolution"):
//     sweep the whole move against every solid, then resolve the hits IN ORDER OF TIME
//     (nearest first); each hit moves the box to where it touches and the rest of the move
//     goes on from there, re-swept with the velocity as changed so far. Resolving in the order the
//     solids happen to be stored instead makes a box sliding along a floor made of separate tiles
//     catch on the seams between tiles: the next tile's corner is "hit" from the side before the
//     floor under the box has taken the downward speed away. Pass sortByTime = false to see that
//     snag.
//   - moveBoxPerAxis: move along x, push out of anything overlapped along x; then
//     the same along y. Simple and seam-free, but it is a discrete test: a step longer than
//     a wall is thick can pass through it (see Tunnelling.h).
//
// Units: pixels, seconds, pixels per second. Solids are still; the mover is the only thing
// moving. The edge rules of Sweep.h and Overlap.h apply: ending exactly touching a solid is
// not a collision, so a box resting on a floor or sliding along a wall is not stopped by it.
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

#include <vector>

namespace hitbox
{

struct MoveResult
{
    Box box;               // where the mover ends up
    Vec2 velocity;         // the velocity to keep: the parts into each surface hit removed
    std::vector<Hit> hits; // the hits resolved, in the order they were resolved
};

// Sweeps `box` by velocity * dt against every solid and slides off each hit in time order
// (the box moves to the hit, loses its speed into that face, and goes on for the rest of the
// step); hits at the same time go in order of how much face they touch
// (so a box exactly over a seam rests on the tile under it before the next tile's corner). A box
// that starts overlapping a solid is first pushed out of it (the push-out of boxVsBoxContact). Up
// to three rounds, so that a slide that turns into another solid (an inside corner) is caught too.
// dt <= 0, NaN or infinite input: no move.
MoveResult moveBoxAndSlide(const Box& box, Vec2 velocity, float dt, const std::vector<Box>& solids,
                           bool sortByTime = true);

// The per-axis move: x first, then y; after each, push out of every solid overlapped,
// against the direction of that axis's motion, and zero that axis's velocity. Each Hit has
// time = the fraction of that axis's move kept, the face normal, the depth pushed out, and
// the middle of the touching edge as point. A solid overlapped while not moving on that axis
// is left for the other axis (or, if neither moves, pushed out as boxVsBoxContact says).
MoveResult moveBoxPerAxis(const Box& box, Vec2 velocity, float dt, const std::vector<Box>& solids);

} // namespace hitbox
