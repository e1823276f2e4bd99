#include "Framework/Collision.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/sfml/Conversions.h"

namespace
{

// Hitbox's world collision box (its negative sizes already normalised).
hitbox::Box boxOf(const GameObject& object)
{
    return hitbox::toBox(object.getCollisionBox());
}

} // namespace

bool Collision::checkBoundingBox(const GameObject& first, const GameObject& second)
{
    return &first != &second && hitbox::boxVsBox(boxOf(first), boxOf(second));
}

bool Collision::checkBoundingBox(const GameObject& object, const sf::Vector2i& point)
{
    return hitbox::pointInBox(hitbox::toVec2(point), boxOf(object));
}

bool Collision::checkBoundingCircle(const GameObject& first, const GameObject& second)
{
    return &first != &second &&
           hitbox::circleVsCircle(first.getBoundingCircle(), second.getBoundingCircle());
}
