#include "Framework/Collision.h"

#include "hitbox/geometry/Overlap.h"

#include <algorithm>

namespace
{

// The one place where the course's SFML 3 types meet Hitbox's geometry types.
hitbox::Box toGeometryBox(const sf::FloatRect& box)
{
    return {box.position.x, box.position.y, box.size.x, box.size.y};
}

hitbox::Circle inscribedCircle(const GameObject& object)
{
    const sf::FloatRect box = object.getCollisionBox();
    hitbox::Circle circle;
    circle.center = {box.position.x + box.size.x / 2.f, box.position.y + box.size.y / 2.f};
    circle.radius = std::min(box.size.x, box.size.y) / 2.f;
    return circle;
}

} // namespace

bool Collision::checkBoundingBox(const GameObject& first, const GameObject& second)
{
    return &first != &second && hitbox::boxVsBox(toGeometryBox(first.getCollisionBox()),
                                                 toGeometryBox(second.getCollisionBox()));
}

bool Collision::checkBoundingBox(const GameObject& object, const sf::Vector2i& point)
{
    return hitbox::pointInBox(
        hitbox::Vec2(static_cast<float>(point.x), static_cast<float>(point.y)),
        toGeometryBox(object.getCollisionBox()));
}

bool Collision::checkBoundingCircle(const GameObject& first, const GameObject& second)
{
    return &first != &second &&
           hitbox::circleVsCircle(inscribedCircle(first), inscribedCircle(second));
}
