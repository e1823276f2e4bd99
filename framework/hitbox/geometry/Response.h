// Response.h - what to do once a test has found a hit: slide, bounce, push out, share speed.
//
// Detection (Overlap.h, Sweep.h, SweptCircle.h, Polygon.h, Capsule.h) says WHAT happened;
// these turn its result into new velocities or positions. Units: pixels, seconds, pixels per
// second. Normals point out of what was hit towards what moves (Shapes.h) and are used as
// given (the detection functions always give a unit normal with a hit).
// RANGE: velocities up to 1e6 px/s per axis and contacts from the tests (so within Range.h's
// +-exactRange) give answers exact up to float rounding (tests/geometry/GeometryRangeTest.cpp).
// Beyond that the float products may overflow to infinity; NaN or infinite input is returned
// unchanged (or (0, 0) for pushOutOffset).
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

namespace hitbox
{

// The velocity for THIS step that stops at the surface at hit.time and slides along it for the
// rest: v + n * |v . n| * (1 - t) (javidx9, "Arbitrary Rectangle Collision Detection &
// Resolution"). No hit, or already moving away (v . n >= 0): velocity unchanged.
[[nodiscard]] Vec2 slideVelocity(Vec2 velocity, const Hit& hit);

// The velocity reflected off a surface: the part into it reversed and scaled by `restitution`
// (1 = perfectly bouncy, 0 = stops dead, like a slide; clamped to [0, 1]), the part along it
// kept. Already moving away (velocity . normal >= 0): unchanged, never pulled into the wall.
[[nodiscard]] Vec2 bounceVelocity(Vec2 velocity, Vec2 normal, float restitution);

// The push-out's outward rounding, as a fraction of the contact's scale (the largest of
// |point.x|, |point.y|, the depth and 1 px): 1e-5, ten times the depth's float error that
// Range.h states. It is at most 0.01 px for shapes within 1000 px of the origin.
constexpr float pushOutSlop = 1e-5f;

// How far to move A so it stops overlapping B: the minimum translation vector, normal *
// depth, rounded OUTWARD by pushOutSlop, so that afterwards the pair does not collide (a
// push of exactly the float depth lands on touching give or take 1e-6 of the coordinates,
// often still inside). Checked for every shape pair over 10^6 cases each
// (tests/long/PushOutTest.cpp). No hit, or a depth that is not finite: (0, 0).
[[nodiscard]] Vec2 pushOutOffset(const Contact& contact);

// The two velocities after a collision.
struct VelocityPair
{
    Vec2 first;
    Vec2 second;
};
// Two bodies that bump along `normal` (out of the second towards the first, a Contact's normal
// with A = first): only the speeds along the normal change; momentum is kept, and with
// restitution 1 so is kinetic energy. Masses in any unit (only their ratio matters); an
// infinite mass is an immovable wall. A mass <= 0, NaN or below about 1e-38 (no float
// inverse), or bodies already moving apart: velocities unchanged.
[[nodiscard]] VelocityPair elasticCollision(Vec2 firstVelocity, float firstMass,
                                            Vec2 secondVelocity, float secondMass, Vec2 normal,
                                            float restitution = 1.f);

} // namespace hitbox
