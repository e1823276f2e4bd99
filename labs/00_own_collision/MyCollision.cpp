#include "MyCollision.h"

#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics/Rect.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
// An sf::FloatRect as its four sides, turned the right way round. (The only place this lab
// reads a FloatRect's fields: SFML 3 renamed them.)
Sides sidesOf(const sf::FloatRect& box)
{
    const hitbox::Box plain = hitbox::toBox(box);
    const float left = plain.left, top = plain.top;
    const float width = plain.width, height = plain.height;
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

// [slide:lab00-world-box]
Sides MyCollision::worldBox(const hitbox::GameObject& object)
{
    // BEGIN TASK 1: the collision box in world coordinates
    // The local box is measured from the origin point, but getTransform() expects the
    // shape's own coordinates, which start at its top-left corner: add the origin first.
    // Rotated, the four corners land anywhere, so the world box is the smallest upright box
    // around all four (Ericson, Real-Time Collision Detection, 4.2.6).
    const Sides local = localCollisionBox(object);
    const std::array<sf::Vector2f, 4> corners = {
        sf::Vector2f(local.left, local.top), sf::Vector2f(local.right, local.top),
        sf::Vector2f(local.right, local.bottom), sf::Vector2f(local.left, local.bottom)};
    Sides world;
    for (std::size_t index = 0; index < corners.size(); ++index)
    {
        const sf::Vector2f corner =
            object.getTransform().transformPoint(corners[index] + object.getOrigin());
        world.left = index == 0 ? corner.x : std::min(world.left, corner.x);
        world.right = index == 0 ? corner.x : std::max(world.right, corner.x);
        world.top = index == 0 ? corner.y : std::min(world.top, corner.y);
        world.bottom = index == 0 ? corner.y : std::max(world.bottom, corner.y);
    }
    return world;
    // STARTER TASK 1
    // // The picture's bounds: right only while the collision box is the whole picture.
    // return sidesOf(object.getGlobalBounds());
    // END TASK 1
}
// [/slide]

// [slide:lab00-box-box]
bool MyCollision::checkBoundingBox(hitbox::GameObject* first, hitbox::GameObject* second)
{
    // BEGIN TASK 2: box against box
    if (!canCollide(first, second))
        return false;
    const Sides a = worldBox(*first);
    const Sides b = worldBox(*second);
    // They overlap when their x ranges overlap AND their y ranges overlap. Strict "<":
    // boxes that only touch do not collide, and any NaN makes a comparison false.
    return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
    // STARTER TASK 2
    // (void)first;
    // (void)second;
    // return false;
    // END TASK 2
}
// [/slide]

bool MyCollision::checkBoundingBox(hitbox::GameObject* object, sf::Vector2f point)
{
    // BEGIN TASK 3: a point in a box
    if (!canCollide(object))
        return false;
    const Sides box = worldBox(*object);
    // Strict: a point exactly on an edge is outside.
    return box.left < point.x && point.x < box.right && box.top < point.y && point.y < box.bottom;
    // STARTER TASK 3
    // (void)object;
    // (void)point;
    // return false;
    // END TASK 3
}

// [slide:lab00-bounding-circle]
WorldCircle MyCollision::worldCircle(const hitbox::GameObject& object)
{
    // BEGIN TASK 4: the bounding circle
    // The circle inside the collision box, not inside the picture: its radius is half the
    // shorter side of the *scaled* box (a mirrored object has a negative scale).
    const Sides local = localCollisionBox(object);
    const float width = (local.right - local.left) * std::abs(object.getScale().x);
    const float height = (local.bottom - local.top) * std::abs(object.getScale().y);
    const sf::Vector2f localCenter((local.left + local.right) / 2.f,
                                   (local.top + local.bottom) / 2.f);
    return {object.getTransform().transformPoint(localCenter + object.getOrigin()),
            std::min(width, height) / 2.f};
    // STARTER TASK 4
    // // The circle inside the picture's bounds: right only for an upright object whose
    // // collision box is the whole picture.
    // const Sides bounds = sidesOf(object.getGlobalBounds());
    // return {{(bounds.left + bounds.right) / 2.f, (bounds.top + bounds.bottom) / 2.f},
    //         std::min(bounds.right - bounds.left, bounds.bottom - bounds.top) / 2.f};
    // END TASK 4
}

bool MyCollision::checkBoundingCircle(hitbox::GameObject* first, hitbox::GameObject* second)
{
    // BEGIN TASK 4: the bounding circle
    if (!canCollide(first, second))
        return false;
    const WorldCircle a = worldCircle(*first);
    const WorldCircle b = worldCircle(*second);
    // Compare squares: distance < r1 + r2 exactly when distance² < (r1 + r2)², and no
    // square root is needed.
    const sf::Vector2f between = a.center - b.center;
    const float reach = a.radius + b.radius;
    return between.x * between.x + between.y * between.y < reach * reach;
    // STARTER TASK 4
    // (void)first;
    // (void)second;
    // return false;
    // END TASK 4
}
// [/slide]

// [slide:lab00-circle-box]
bool MyCollision::checkCircleBox(hitbox::GameObject* circleObject, hitbox::GameObject* boxObject)
{
    // BEGIN TASK 5: circle against box
    if (!canCollide(circleObject, boxObject))
        return false;
    const WorldCircle circle = worldCircle(*circleObject);
    const Sides box = worldBox(*boxObject);
    if (!(box.left <= box.right && box.top <= box.bottom))
        return false; // NaN sides: std::clamp below would hand back the centre itself
    // A centre strictly inside always collides, even a circle of radius 0 (a point).
    const sf::Vector2f center = circle.center;
    if (box.left < center.x && center.x < box.right && box.top < center.y && center.y < box.bottom)
        return true;
    // Otherwise the point of the box closest to the centre is the centre clamped into the
    // box (Ericson, Real-Time Collision Detection, 5.1.3); the circle reaches strictly past it.
    const sf::Vector2f closest(std::clamp(center.x, box.left, box.right),
                               std::clamp(center.y, box.top, box.bottom));
    const sf::Vector2f away = center - closest;
    return away.x * away.x + away.y * away.y < circle.radius * circle.radius;
    // STARTER TASK 5
    // (void)circleObject;
    // (void)boxObject;
    // return false;
    // END TASK 5
}
// [/slide]
