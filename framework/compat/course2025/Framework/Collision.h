// Framework/Collision.h (2025-26 course framework) - collision tests between GameObjects,
// on Hitbox's collision maths (hitbox/geometry/Overlap.h), so the edge rule is Hitbox's:
// touching is not colliding.
//
// The course's bounding circle (radius getSize().x / 2, measured from the position) is
// wrong once the origin moves, the shape is not square or the object is scaled. Here, as
// for the older labs, it is Hitbox's (GameObject::getBoundingCircle): the circle inscribed
// in the collision box, scaled and moved with the object.
//
// As in the course's framework, the tests look only at the shapes: isCollider() and
// isAlive() are for the lab's own loops. An object tested against itself never collides.
#pragma once

#include "Framework/GameObject.h"

class Collision
{
public:
    static bool checkBoundingBox(const GameObject& first, const GameObject& second);
    // Is a point (the mouse, in window pixels) inside the object's collision box?
    static bool checkBoundingBox(const GameObject& object, const sf::Vector2i& point);
    static bool checkBoundingCircle(const GameObject& first, const GameObject& second);
};
