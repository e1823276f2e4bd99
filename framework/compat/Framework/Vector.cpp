#include "Framework/Vector.h"

#include "hitbox/geometry/Vec2.h"
#include "hitbox/sfml/Conversions.h"

// The course's names for Hitbox's vector maths (hitbox/geometry/Vec2.h): one home for each rule.

float Vector::magnitude(sf::Vector2f vector)
{
    return hitbox::length(hitbox::toVec2(vector));
}

sf::Vector2f Vector::normalise(sf::Vector2f vector)
{
    // No direction (zero, NaN, infinite): the vector comes back unchanged.
    return hitbox::toSfml(hitbox::unitVectorOr(hitbox::toVec2(vector), hitbox::toVec2(vector)));
}

float Vector::dot(sf::Vector2f a, sf::Vector2f b)
{
    return hitbox::dot(hitbox::toVec2(a), hitbox::toVec2(b));
}
