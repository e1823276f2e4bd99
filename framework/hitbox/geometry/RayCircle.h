// RayCircle.h - where does a ray (a segment) enter and leave a circle?
//
// The points of the segment are start + t * (end - start), 0 <= t <= 1; they are on the
// circle's rim where |start + t * d - centre| = radius, a quadratic in t (Ericson, Real-Time
// Collision Detection, 5.3.2 "Intersecting ray or segment against sphere"). Its discriminant
// says miss (< 0), graze (= 0) or cross (> 0); its two roots are the near (entry) and far
// (exit) times. Line of sight, bullets and a mouse-aimed laser against round things use it.
// Units: pixels; the maths runs in double.
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

// What segmentVsCircle found.
struct RayCircleResult
{
    bool hit = false;           // the segment gets strictly inside the circle at 0 <= t < 1
    float nearTime = 1.f;       // when it enters: 0 when it started inside
    float farTime = 1.f;        // when it leaves (may be > 1: beyond the segment's end)
    Vec2 point;                 // where it enters: on the rim, or `start` when startedInside
    Vec2 normal;                // unit, centre to `point`; (0, 0) when startedInside or no hit
    bool startedInside = false; // `start` strictly inside the circle (then nearTime == 0)
};

// The segment from `start` to `end` against `circle`. EDGE RULE (touching is not colliding,
// as segmentVsBox): a segment that only grazes the rim (a tangent), or reaches it only at
// its end (t = 1), is no hit; starting on the rim is a hit at time 0 only when it heads
// inside. A zero-length segment hits only when it starts strictly inside. Radius 0 (no area)
// or negative, NaN, infinity, or any coordinate or radius outside +-exactRange (Range.h):
// no hit. Huge values inside the range: the times are exact up to float rounding.
[[nodiscard]] RayCircleResult segmentVsCircle(Vec2 start, Vec2 end, const Circle& circle);

} // namespace hitbox
