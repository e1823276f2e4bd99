// A second correct MyCollision, written differently from the lab's solution: the pack must
// pass it. It works on the world box from SFML's transformRect, tests boxes as "not
// separated on either axis" (with NaN caught first), measures circles by their corner
// points, and tests a circle against a box by the distance outside the box on each axis.
#include "MyCollision.h"

#include "hitbox/objects/GameObject.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/Rect.hpp>

#include <cmath>
#include <utility>

namespace
{
Sides sidesOf(const sf::FloatRect& box)
{
    const sf::Vector2f from = hitbox::rectPosition(box), size = hitbox::rectSize(box);
    Sides sides{from.x, from.y, from.x + size.x, from.y + size.y};
    if (sides.right < sides.left)
        std::swap(sides.left, sides.right);
    if (sides.bottom < sides.top)
        std::swap(sides.top, sides.bottom);
    return sides;
}

bool isNumber(const Sides& sides)
{
    return !std::isnan(sides.left + sides.right + sides.top + sides.bottom);
}

// How far x lies outside [low, high]; 0 inside.
float outside(float x, float low, float high)
{
    if (x < low)
        return low - x;
    if (x > high)
        return x - high;
    return 0.f;
}
} // namespace

bool MyCollision::canCollide(const hitbox::GameObject* object)
{
    return object && object->isAlive() && object->isCollider();
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
    const Sides local = localCollisionBox(object);
    const sf::Vector2f shift = object.getOrigin();
    const sf::FloatRect inShape({local.left + shift.x, local.top + shift.y},
                                {local.right - local.left, local.bottom - local.top});
    return sidesOf(object.getTransform().transformRect(inShape));
}

bool MyCollision::checkBoundingBox(hitbox::GameObject* first, hitbox::GameObject* second)
{
    if (!canCollide(first, second))
        return false;
    const Sides a = worldBox(*first);
    const Sides b = worldBox(*second);
    if (!isNumber(a) || !isNumber(b))
        return false;
    const bool apartOnX = a.right <= b.left || b.right <= a.left;
    const bool apartOnY = a.bottom <= b.top || b.bottom <= a.top;
    return !apartOnX && !apartOnY;
}

bool MyCollision::checkBoundingBox(hitbox::GameObject* object, sf::Vector2f point)
{
    if (!canCollide(object))
        return false;
    const Sides box = worldBox(*object);
    const bool onOrOutside = !(point.x > box.left) || !(point.x < box.right) ||
                             !(point.y > box.top) || !(point.y < box.bottom);
    return !onOrOutside;
}

WorldCircle MyCollision::worldCircle(const hitbox::GameObject& object)
{
    const Sides local = localCollisionBox(object);
    const sf::Transform& toWorld = object.getTransform();
    const sf::Vector2f origin = object.getOrigin();
    // The sides' lengths after scaling, from where two corners land (rotation keeps them).
    const sf::Vector2f topLeft =
        toWorld.transformPoint({local.left + origin.x, local.top + origin.y});
    const sf::Vector2f topRight =
        toWorld.transformPoint({local.right + origin.x, local.top + origin.y});
    const sf::Vector2f bottomLeft =
        toWorld.transformPoint({local.left + origin.x, local.bottom + origin.y});
    const float across = std::hypot(topRight.x - topLeft.x, topRight.y - topLeft.y);
    const float down = std::hypot(bottomLeft.x - topLeft.x, bottomLeft.y - topLeft.y);
    const sf::Vector2f center =
        toWorld.transformPoint({origin.x + local.left + (local.right - local.left) / 2.f,
                                origin.y + local.top + (local.bottom - local.top) / 2.f});
    return {center, (across < down ? across : down) * 0.5f};
}

bool MyCollision::checkBoundingCircle(hitbox::GameObject* first, hitbox::GameObject* second)
{
    if (!canCollide(first, second))
        return false;
    const WorldCircle a = worldCircle(*first);
    const WorldCircle b = worldCircle(*second);
    const float dx = b.center.x - a.center.x;
    const float dy = b.center.y - a.center.y;
    const float reach = a.radius + b.radius;
    return dx * dx + dy * dy < reach * reach;
}

bool MyCollision::checkCircleBox(hitbox::GameObject* circleObject, hitbox::GameObject* boxObject)
{
    if (!canCollide(circleObject, boxObject))
        return false;
    const WorldCircle circle = worldCircle(*circleObject);
    const Sides box = worldBox(*boxObject);
    if (!isNumber(box) || std::isnan(circle.center.x + circle.center.y + circle.radius))
        return false;
    const float dx = outside(circle.center.x, box.left, box.right);
    const float dy = outside(circle.center.y, box.top, box.bottom);
    if (dx == 0.f && dy == 0.f) // the centre is in the box or on its edge
        return box.left < circle.center.x && circle.center.x < box.right &&
                       box.top < circle.center.y && circle.center.y < box.bottom
                   ? true
                   : circle.radius > 0.f;
    return dx * dx + dy * dy < circle.radius * circle.radius;
}
