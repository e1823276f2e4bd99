// Tunnelling.h - can one step of a discrete test jump right through a target?
//
// A discrete test (Overlap.h) only looks at where things are at the end of each step, so a
// step that carries the mover from one side of a thin target to the other is never seen:
// "bullet through paper" (Katy Coe, "2D Platform Games Part 1"). Units: pixels.
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

// True when the step `displacement` is at least the two boxes' sizes added on some axis (long
// enough to go from touching one side to touching the other) and the step's swept bounds
// share area with the target. A diagonal corner clip can be missed at any speed: only a sweep
// (Sweep.h) catches that. NaN or infinite input: false. Negative sizes: read as normalised().
// Range: any finite box and step (plain comparisons of sums; exact within Range.h's
// +-exactRange, and a sum past about 3.4e38 is infinite: false).
[[nodiscard]] bool canTunnel(const Box& mover, Vec2 displacement, const Box& target);

} // namespace hitbox
