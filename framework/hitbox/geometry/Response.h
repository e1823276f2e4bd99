// Response.h - what to do once a test has found a hit: slide, bounce, push out, share speed.
//
// Detection (Overlap.h, Sweep.h, SweptCircle.h, Polygon.h, Capsule.h) says WHAT happened;
// these turn its result into new velocities or positions. Units: pixels, seconds, pixels per
// second. Normals point out of what was hit towards what moves (Shapes.h) and are used as
// given (the detection functions always give a unit normal with a hit).
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

namespace hitbox
{

// The velocity for THIS step that stops at the surface at hit.time and slides along it for the
// rest: v + n * |v . n| * (1 - t) (javidx9, "Arbitrary Rectangle Collision Detection &
// Resolution"). No hit, or already moving away (v . n >= 0): velocity unchanged.
Vec2 slideVelocity(Vec2 velocity, const Hit& hit);

// The velocity reflected off a surface: the part into it reversed and scaled by `restitution`
// (1 = perfectly bouncy, 0 = stops dead, like a slide; clamped to [0, 1]), the part along it
// kept. Already moving away (velocity . normal >= 0): unchanged, never pulled into the wall.
Vec2 bounceVelocity(Vec2 velocity, Vec2 normal, float restitution);

// How far to move A so it stops overlapping B: normal * depth (the minimum translation
// vector), after which they touch, which is not a collision. No hit: (0, 0).
Vec2 pushOutOffset(const Contact& contact);

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
VelocityPair elasticCollision(Vec2 firstVelocity, float firstMass, Vec2 secondVelocity,
                              float secondMass, Vec2 normal, float restitution = 1.f);

} // namespace hitbox
