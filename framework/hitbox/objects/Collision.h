// Collision.h - the friendly facade: collision tests between GameObjects.
//
// Every function here reads the objects' world-space collision box or bounding circle and
// calls the plain-value tests in geometry/Overlap.h, so the edge rule is the same:
// touching is not colliding. The lecture's calls work as they are:
//     if (Collision::checkBoundingCircle(&ball1, &ball2)) { ... }
//
// Defined answers for objects that cannot collide: a null pointer, an object that is not a
// collider, a dead object, or an object tested against itself gives false (and a Contact
// with hit == false).
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/objects/ShapeTable.h"

#include <SFML/System/Vector2.hpp>

namespace hitbox
{
class GameObject;

class Collision
{
public:
    // Every function is static: call Collision::checkBoundingBox(...) directly. Old lab code
    // also writes `Collision collision;` or derives from Collision; both still work.

    // Bounding circles (no square root). The circles come from each object's
    // getBoundingCircle(): by default the circle inside its collision box.
    [[nodiscard]] static bool checkBoundingCircle(hitbox::GameObject* first,
                                                  hitbox::GameObject* second);
    // Axis-aligned collision boxes.
    [[nodiscard]] static bool checkBoundingBox(hitbox::GameObject* first,
                                               hitbox::GameObject* second);
    // Is a point inside the object's collision box? The point is in world coordinates:
    // Hitbox's Input gives the mouse in world coordinates, so this is right after a resize.
    [[nodiscard]] static bool checkBoundingBox(hitbox::GameObject* object, sf::Vector2f point);
    [[nodiscard]] static bool checkBoundingBox(hitbox::GameObject* object, sf::Vector2i point);
    // The first object's bounding circle against the second object's collision box.
    [[nodiscard]] static bool checkCircleBox(hitbox::GameObject* circleObject,
                                             hitbox::GameObject* boxObject);

    // The same tests, telling how they collide: the normal points out of `second` towards
    // `first`; moving `first` by normal * depth separates them.
    [[nodiscard]] static hitbox::Contact getBoundingCircleContact(hitbox::GameObject* first,
                                                                  hitbox::GameObject* second);
    [[nodiscard]] static hitbox::Contact getBoundingBoxContact(hitbox::GameObject* first,
                                                               hitbox::GameObject* second);
    [[nodiscard]] static hitbox::Contact getCircleBoxContact(hitbox::GameObject* circleObject,
                                                             hitbox::GameObject* boxObject);
    // Any two shape kinds of `shapes` (ShapeTable.h; Hitbox's Box and Circle by default): the
    // three tests above are this one with the kinds filled in.
    [[nodiscard]] static hitbox::Contact
    getContact(hitbox::GameObject* first, hitbox::ShapeKind firstKind, hitbox::GameObject* second,
               hitbox::ShapeKind secondKind,
               const hitbox::ShapeTable& shapes = hitbox::ShapeTable::standard());
};

} // namespace hitbox
