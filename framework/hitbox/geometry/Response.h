// Response.h - what to do once a test has found a hit: slide, bounce, push out, share speed.
//
// Detection (Overlap.h, Sweep.h, SweptCircle.h, Polygon.h, Capsule.h) says WHAT happened;
// these small functions turn that answer into new velocities or positions. They only read
// the result values, so they work with every test.
//
// Units: pixels, seconds, pixels per second. Normals are unit vectors pointing out of the
// thing that was hit towards the thing that moves (the convention of Shapes.h).
//
// EDGE RULES:
//   - No hit (hit == false): the velocity (or offset) comes back unchanged (or zero).
//   - Moving away from the surface already (velocity . normal >= 0): nothing to remove,
//     the velocity comes back unchanged. So a response never pulls an object into a wall.
//   - A zero, NaN or non-unit normal is used as given; the detection functions always give
//     a unit normal with a hit.
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

namespace hitbox
{

// javidx9's slide: the velocity for THIS step, so that moving by velocity * dt stops the
// mover at the surface (time t) and keeps the rest of its motion along the surface:
//   v + n * |v . n| * (1 - t)
// Only the part of the velocity going INTO the surface is taken away, and only for the part
// of the step after the impact (1 - t). Started inside (t = 0): the whole inward part goes.
Vec2 slideVelocity(Vec2 velocity, const Hit& hit);

// Reflect the velocity off a surface: the part into the surface is reversed and scaled by
// `restitution` (1 = perfectly bouncy, 0 = stops dead against it, like a slide). The part
// along the surface is kept. Restitution is clamped to [0, 1].
Vec2 bounceVelocity(Vec2 velocity, Vec2 normal, float restitution);

// How far to move A so that it stops overlapping B: normal * depth (the minimum translation
// vector). After it they touch, which is not a collision. (0, 0) when there is no hit.
Vec2 pushOutOffset(const Contact& contact);

// Two bodies that bump: new velocities after an elastic collision along `normal` (out of the
// second towards the first, as a Contact's normal with A = first). Momentum is kept and, with
// restitution 1, so is kinetic energy. Only the speeds along
// the normal change. Masses in any unit (only their ratio matters): an infinite mass is an
// immovable wall; a mass <= 0, NaN or too small to invert in float (below about 1e-38), or
// bodies already moving apart, change nothing.
struct VelocityPair
{
    Vec2 first;
    Vec2 second;
};
VelocityPair elasticCollision(Vec2 firstVelocity, float firstMass, Vec2 secondVelocity,
                              float secondMass, Vec2 normal, float restitution = 1.f);

} // namespace hitbox
