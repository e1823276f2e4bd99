// Tunnelling.h - when can a discrete test miss a collision, and how to stop it.
//
// A discrete test (Overlap.h) looks at where things are at the end of each step. If a step
// carries the mover from one side of a target to the other, neither look sees an overlap
// and the mover passes straight through: "bullet through paper" (Katy Coe,
// "2D Platform Games Part 1"). These functions
// say when that can happen, give the swept bounds a broad phase uses to find what a move
// could touch (javidx9, "Arbitrary Rectangle Collision Detection & Resolution"), and clamp a move
// so it stops at the first surface (speculative contacts, as in Katy Coe's "2D Platform Games Part
// 1").
//
// Units: pixels, seconds, pixels per second; `displacement` is the whole move of one step.
// Edge rules: NaN or infinite input never tunnels (false) and never changes a velocity;
// negative box sizes are read as SFML reads them; a negative radius is not a circle (false).
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <vector>

namespace hitbox
{

// True when this step is long enough for the mover to pass right through the target
// between two discrete tests, and the step's swept bounds reach the target. "Long enough":
// on some axis the move is at least the two sizes added on that axis (then the mover can go
// from touching one side to touching the other, and neither end of the step overlaps).
// Note: clipping a corner diagonally can be missed at any speed; only a sweep catches that.
bool canTunnel(const Box& mover, Vec2 displacement, const Box& target);
// Circles: the move is at least the two diameters added, and the mover's path (a capsule)
// reaches the target. That is the head-on case: passing off-centre crosses a shorter chord,
// so a shorter move can already skip it (discreteTestMisses or a sweep catches that).
bool canTunnel(const Circle& mover, Vec2 displacement, const Circle& target);
// A circle against a box: the circle counts as its bounding box (2r by 2r).
bool canTunnel(const Circle& mover, Vec2 displacement, const Box& target);

// True when the sweep says the mover hits the target during the step but the discrete
// test at the start and at the end of the step sees no overlap: the miss actually happens.
bool discreteTestMisses(const Box& mover, Vec2 displacement, const Box& target);
bool discreteTestMisses(const Circle& mover, Vec2 displacement, const Circle& target);

// The smallest box holding the mover at the start and at the end of the step (and so, for a
// box or a circle moving in a straight line, everywhere between). Broad phase: only targets
// that overlap these bounds can be hit this step. NaN input: returned as it comes.
Box sweptBounds(const Box& box, Vec2 displacement);
Box sweptBounds(const Circle& circle, Vec2 displacement);

// Speculative contacts, simplified: the velocity scaled down so that moving by
// velocity * dt ends touching the first solid the box would hit, never inside it (where
// rounding would put it a hair inside, the move is shortened by a float step or two; the box
// is then apart by at most that much). The whole velocity is scaled, so there is no slide;
// see Resolve.h for that. A box already overlapping a solid
// keeps its velocity (pushing out is a separate job). No hit: unchanged.
Vec2 speculativeVelocity(const Box& mover, Vec2 velocity, float dt, const std::vector<Box>& solids);

} // namespace hitbox
