// Sweep.h - where along a move does something first hit a box? Rays, segments, moving boxes.
//
// A discrete test (Overlap.h) only sees where things are at the end of a step, so a fast
// object can jump a thin wall ("bullet through paper"); a sweep follows the whole straight
// move of one step and says WHEN the mover first touches the target. Units: pixels;
// `displacement` is the whole move of the step (velocity * dt): time 0 is its start, 1 its end.
// RANGE (Range.h): segmentVsBox's two ends within +-exactRange, else no hit. The box sweeps
// take any finite boxes and moves (a floor 1e30 px wide is hit at the right time) and are
// exact up to float rounding when every coordinate is within +-exactRange.
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

// What a cast or a sweep found. Same normal convention as Contact (Shapes.h): the normal is
// the surface normal of the target where it was hit, pointing back towards the mover.
struct Hit
{
    bool hit = false;
    float time = 1.f;           // time of impact in [0, 1), a fraction of the move
    Vec2 point;                 // where they touch at that time (on the target's surface)
    Vec2 normal;                // unit length when hit, (0, 0) otherwise
    bool startedInside = false; // already sharing area at time 0 (then time == 0)
    float depth = 0.f;          // how deep the mover already was, only when startedInside

    explicit operator bool() const { return hit; }
};

// The answer for a mover that already shares area with its target at time 0: a hit at
// time 0 with `startedInside`, and the contact's push-out as normal, depth and point.
[[nodiscard]] Hit startedInsideHit(const Contact& overlap);

// A hit found in a moving target's frame (the mover made the relative move), put back in the
// world: the point moves on with the target by targetDisplacement * time. No hit: unchanged.
[[nodiscard]] Hit movedWithTarget(Hit hitSeenFromTarget, Vec2 targetDisplacement);

// The slab method (Ericson, Real-Time Collision Detection, 5.3.3): a point moving from `start`
// to `end` against a box. Hits only when the point passes strictly inside (a point grazing an
// edge does not); `point` is start + time * (end - start). A zero-length segment is
// pointInBox; a zero-size box is never hit (two things with no area). NaN: no hit.
// Both ends must be within +-exactRange (Range.h); outside it: no hit.
[[nodiscard]] Hit segmentVsBox(Vec2 start, Vec2 end, const Box& box);

// A box moving by `displacement` against a still box (Ericson 5.5.8: the slab method against
// the target grown by the mover's size). A hit is coming to SHARE AREA at some 0 <= time < 1;
// `time` is when they first touch, so grazing, moving away or touching only at time 1 is no
// hit, and overlapping already is time 0 with startedInside (boxVsBoxContact's push-out). Exact
// corner: the x axis wins. NaN or infinite: no hit. `point`: the middle of the touching edge.
// Moving to `time` can round to a hair inside: moveBoxAndSlide (Resolve.h) corrects for that.
[[nodiscard]] Hit sweepBoxVsBox(const Box& mover, Vec2 displacement, const Box& target);

// Both boxes move: sweepBoxVsBox of the relative move (moverDisplacement - targetDisplacement),
// same edge rules. `point` is where they touch in the world at that time.
[[nodiscard]] Hit sweepBoxVsMovingBox(const Box& mover, Vec2 moverDisplacement, const Box& target,
                                      Vec2 targetDisplacement);

} // namespace hitbox
