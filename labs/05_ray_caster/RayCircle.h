// RayCircle.h - task 4 of lab 5: a ray against a round pillar.
//
// The points of the ray are from + t * (to - from), 0 <= t <= 1. One is on the circle's rim
// when its distance to the centre is the radius: a quadratic in t, a t^2 + 2 b t + c = 0
// (Ericson, Real-Time Collision Detection, 5.3.2). The framework's version, with near and
// far times in a result struct, is hitbox::segmentVsCircle (hitbox/geometry/RayCircle.h).
#pragma once

#include "hitbox/geometry/Shapes.h"

// What rayCircleTime answers when the ray never gets inside the circle.
constexpr float rayMissed = -1.f;

// The time t in [0, 1) at which the ray from `from` to `to` first gets strictly inside
// `circle`, or rayMissed. Edge rule, touching is not colliding: a ray that only grazes the
// rim, or reaches it only at `to` (t = 1), misses. Starting inside: 0. Starting on the rim:
// 0 when heading inside, else rayMissed. A radius of 0 or less is never hit.
float rayCircleTime(hitbox::Vec2 from, hitbox::Vec2 to, const hitbox::Circle& circle);
