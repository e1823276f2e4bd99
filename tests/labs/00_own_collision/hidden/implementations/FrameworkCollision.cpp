// A third correct MyCollision: every answer forwarded to the framework's own Collision and
// GameObject. The pack must pass it: it is what the random cases compare against.
#include "MyCollision.h"

#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/Rect.hpp>

#include <algorithm>

namespace
{
Sides sidesOf(const sf::FloatRect& box)
{
    const hitbox::Box plain = hitbox::toBox(box);
    const float left = plain.left, top = plain.top, width = plain.width, height = plain.height;
    return {std::min(left, left + width), std::min(top, top + height), std::max(left, left + width),
            std::max(top, top + height)};
}
} // namespace

bool MyCollision::canCollide(const hitbox::GameObject* object)
{
    return object != nullptr && object->isAlive() && object->isCollider();
}

bool MyCollision::canCollide(const hitbox::GameObject* first, const hitbox::GameObject* second)
{
    return first != second && canCollide(first) && canCollide(second);
}

Sides MyCollision::localCollisionBox(const hitbox::GameObject& object)
{
    return sidesOf(object.getLocalCollisionBox());
}

Sides MyCollision::worldBox(const hitbox::GameObject& object)
{
    return sidesOf(object.getCollisionBox());
}

bool MyCollision::checkBoundingBox(hitbox::GameObject* first, hitbox::GameObject* second)
{
    return hitbox::Collision::checkBoundingBox(first, second);
}

bool MyCollision::checkBoundingBox(hitbox::GameObject* object, sf::Vector2f point)
{
    return hitbox::Collision::checkBoundingBox(object, point);
}

WorldCircle MyCollision::worldCircle(const hitbox::GameObject& object)
{
    const hitbox::Circle circle = object.getBoundingCircle();
    return {hitbox::toSfml(circle.center), circle.radius};
}

bool MyCollision::checkBoundingCircle(hitbox::GameObject* first, hitbox::GameObject* second)
{
    return hitbox::Collision::checkBoundingCircle(first, second);
}

bool MyCollision::checkCircleBox(hitbox::GameObject* circleObject, hitbox::GameObject* boxObject)
{
    return hitbox::Collision::checkCircleBox(circleObject, boxObject);
}
