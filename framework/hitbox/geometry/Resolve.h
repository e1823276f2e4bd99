// Resolve.h - move a box through a world of still solid boxes for one step, sliding along them.
//
// One moving box, many still ones (tiles, walls, platforms). Units: pixels, seconds, pixels
// per second. The per-axis alternative (move x, push out, then y) is lab 10's to write.
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

// Sweeps `box` by velocity * dt against every solid and resolves the hits nearest first
// (javidx9, "Arbitrary Rectangle Collision Detection & Resolution"): the box moves to the hit,
// loses its speed into that face and goes on, re-swept, for the rest of the step; up to three
// rounds, so an inside corner stops both ways. Equal times: the hit touching more face first,
// so a box over a tile seam rests on the tile under it. sortByTime = false resolves in storage
// order instead, to show the box snagging on the seams. Ends touching, never inside (touching
// is no collision, so resting on a floor does not stop a slide). Wedged in a gap narrower than
// itself, the box stops (velocity 0) at the last place on its path that touched nothing more
// than an edge. A box starting inside a solid
// is pushed out first (boxVsBoxContact). dt <= 0, NaN or infinite input: no move.
// RANGE (Range.h): the mover's corner and size, and its whole move velocity * dt, each within
// +-exactRange (1e6 px) per axis: then the answer is exact up to float rounding. Outside it
// (e.g. 3e38 px/s): no move (the box where it was, its velocity, no hits). Solids: any finite
// boxes (a huge floor is fine); the mover never ends inside one.
[[nodiscard]] MoveResult moveBoxAndSlide(const Box& box, Vec2 velocity, float dt,
                                         const std::vector<Box>& solids, bool sortByTime = true);

} // namespace hitbox
