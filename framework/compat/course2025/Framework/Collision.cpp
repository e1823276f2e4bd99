#include "Framework/Collision.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/sfml/Conversions.h"

namespace
{

// Hitbox's box (one negative-size rule: normalised) and its inscribed circle: the same
// shapes the older labs' GameObject gives.
hitbox::Box boxOf(const GameObject& object)
{
    return hitbox::normalised(hitbox::toBox(object.getCollisionBox()));
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
    return &first != &second && hitbox::circleVsCircle(hitbox::inscribedCircle(boxOf(first)),
                                                       hitbox::inscribedCircle(boxOf(second)));
}
