#include "hitbox/geometry/Response.h"

#include "hitbox/geometry/Vec2.h"

#include <cmath>

namespace hitbox
{

// [slide:response-slide]
Vec2 slideVelocity(Vec2 velocity, const Hit& hit)
{
    if (!hit.hit)
        return velocity;
    // How fast the mover goes INTO the surface (0 when moving away or along it).
    const float intoSurface = std::fmax(-dot(velocity, hit.normal), 0.f);
    // Cancel that part for the rest of the step after the impact (javidx9's (1 - t)).
    // Moving by the result for the whole step ends exactly touching the surface.
    return velocity + hit.normal * intoSurface * (1.f - hit.time);
}
// [/slide]

// [slide:response-bounce]
Vec2 bounceVelocity(Vec2 velocity, Vec2 normal, float restitution)
{
    const float bounciness = std::fmin(std::fmax(restitution, 0.f), 1.f);
    const float alongNormal = dot(velocity, normal);
    if (!(alongNormal < 0.f))
        return velocity; // already leaving the surface (or no normal): leave it alone
    // Take the inward part away, then add it back reversed and scaled by the restitution.
    return velocity - normal * ((1.f + bounciness) * alongNormal);
}
// [/slide]

Vec2 pushOutOffset(const Contact& contact)
{
    if (!contact.hit || !std::isfinite(contact.depth))
        return {0.f, 0.f};
    const float scale = std::fmax(std::fmax(std::fabs(contact.point.x), std::fabs(contact.point.y)),
                                  std::fmax(contact.depth, 1.f));
    return contact.normal * (contact.depth + pushOutSlop * scale);
}

// [slide:response-elastic]
VelocityPair elasticCollision(Vec2 firstVelocity, float firstMass, Vec2 secondVelocity,
                              float secondMass, Vec2 normal, float restitution)
{
    const VelocityPair unchanged{firstVelocity, secondVelocity};
    if (!(firstMass > 0.f) || !(secondMass > 0.f))
        return unchanged;
    // 1 / mass: 0 for an infinite mass (an immovable wall).
    const float firstInverse = 1.f / firstMass;
    const float secondInverse = 1.f / secondMass;
    if (firstInverse + secondInverse == 0.f)
        return unchanged; // two immovable walls
    if (!std::isfinite(firstInverse) || !std::isfinite(secondInverse))
        return unchanged; // a mass so small (below about 1e-38) that 1 / mass overflows
    // How fast the first closes in on the second along the normal (< 0 when approaching).
    const float closing = dot(firstVelocity - secondVelocity, normal);
    if (!(closing < 0.f))
        return unchanged;
    // The impulse that, shared in inverse proportion to the masses, reverses the closing
    // speed (scaled by the restitution): momentum is kept because the two shares are equal
    // and opposite.
    const float bounciness = std::fmin(std::fmax(restitution, 0.f), 1.f);
    const float impulse = -(1.f + bounciness) * closing / (firstInverse + secondInverse);
    return {firstVelocity + normal * (impulse * firstInverse),
            secondVelocity - normal * (impulse * secondInverse)};
}
// [/slide]

} // namespace hitbox
