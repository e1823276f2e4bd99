// Sweep.h - where along a move does something first hit a box? Rays, segments, moving boxes.
//
// A discrete test (Overlap.h) only looks at where things ARE at the end of a step, so a fast
// object can jump over a thin wall between two frames ("bullet through paper").
// A sweep looks at the whole straight-line move of one step and answers WHEN, as a fraction
// `time` of the move, the mover first touches the target.
//
// Units: pixels. `displacement` is the whole move for this step (velocity * dt), so
// time 0 is where the mover starts and time 1 is where it ends up.
//
// EDGE RULES (the same "share area" rule as Overlap.h, followed through time):
//   - A sweep hits when the mover would come to SHARE AREA with the target during the step
//     (0 <= t < 1). The reported `time` is when they first touch, so moving there leaves
//     the mover touching, and touching is not a collision. In floats, `start + move * time`
//     can round to a hair inside (about one time in five in random tests); moveBoxAndSlide
//     (Resolve.h) and speculativeVelocity (Tunnelling.h) correct for that, so use them, or
//     expect the next sweep to report startedInside with a tiny depth.
//   - Sliding along a surface while exactly touching: no hit.
//   - Moving away from a touching contact: no hit.
//   - Moving into a surface from exact contact: hit at time 0, startedInside == false.
//   - Touching only at the very end of the step (t == 1): no hit (they never share area).
//   - Already sharing area at time 0: hit, startedInside == true, time 0, and `normal`,
//     `depth`, `point` are the push-out of boxVsBoxContact (least-overlap axis, ties to x).
//   - Hitting an exact corner (both axes entered at the same instant): the x axis wins, so
//     the normal is (+-1, 0), never (0, 0).
//   - Zero displacement / zero-length segment: no move, so it is the discrete test:
//     startedInside when already overlapping, otherwise no hit.
//   - Moving parallel to an axis: that axis never changes, no division by zero happens
//     (the divide-by-zero case in javidx9's video).
//   - NaN or infinite input: no hit.
//   - Zero-size boxes follow Overlap.h: a point or line collides when strictly inside; two
//     things with no area (a segment against a zero-size box) never hit.
//   - Negative box sizes are read as SFML reads them (see normalised()).
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

// What a cast or a sweep found. Same normal convention as Contact (Shapes.h): the normal is
// the surface normal of the target where it was hit, pointing back towards the mover.
struct Hit
{
    bool hit = false;
    float time = 1.f;           // time of impact in [0, 1], a fraction of the move
    Vec2 point;                 // where they touch at that time (on the target's surface)
    Vec2 normal;                // unit length when hit, (0, 0) otherwise
    bool startedInside = false; // already sharing area at time 0 (then time == 0)
    float depth = 0.f;          // how deep the mover already was, only when startedInside

    explicit operator bool() const { return hit; }
};

// The answer for a mover that already shares area with its target at time 0: a hit at
// time 0 with `startedInside`, and the contact's push-out as normal, depth and point.
Hit startedInsideHit(const Contact& overlap);

// The slab method (Ericson, 5.3.3): the segment from `start` to `end` against a box. A segment is
// a point moving from start to end, so it hits when that point passes strictly inside the
// box. `point` is start + time * (end - start).
Hit segmentVsBox(Vec2 start, Vec2 end, const Box& box);

// A box moving by `displacement` against a box that stays still. The idea (Ericson, 5.5.8): grow
// the target by the mover's size (the Minkowski sum) and cast the mover's centre through it
// with the slab method. `point` is the middle of the touching edge (or the corner).
Hit sweepBoxVsBox(const Box& mover, Vec2 displacement, const Box& target);

// Both boxes move during the step. Only the relative move matters, so this sweeps the mover
// by (moverDisplacement - targetDisplacement) against a still target. `point` is where they
// touch in the world at that time (the target has moved by time * targetDisplacement).
Hit sweepBoxVsMovingBox(const Box& mover, Vec2 moverDisplacement, const Box& target,
                        Vec2 targetDisplacement);

} // namespace hitbox
