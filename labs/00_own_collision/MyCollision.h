// MyCollision.h - your own version of the framework's Collision class.
//
// The same questions Collision answers (framework/hitbox/objects/Collision.h), written by
// you, with the same edge rule: two shapes collide only when one reaches strictly inside
// the other. Touching edges, touching corners and a point exactly on an edge do NOT
// collide; NaN coordinates never collide. The grading tests compare every answer with the
// framework's.
#pragma once

#include <SFML/System/Vector2.hpp>

namespace hitbox
{
class GameObject;
}

// A box by its four sides in world pixels (left <= right, top <= bottom).
struct Sides
{
    float left = 0.f;
    float top = 0.f;
    float right = 0.f;
    float bottom = 0.f;
};

// A circle in world pixels.
struct WorldCircle
{
    sf::Vector2f center;
    float radius = 0.f;
};

class MyCollision
{
public:
    MyCollision() = delete; // a static class, like Collision

    // Given: the framework's rule for objects that cannot collide. False for a null
    // pointer, a dead object, one that is not a collider, or an object against itself.
    static bool canCollide(const hitbox::GameObject* object);
    static bool canCollide(const hitbox::GameObject* first, const hitbox::GameObject* second);
    // Given: the object's collision box measured from its origin point, in unscaled
    // pixels, turned the right way round (a negative size spans backwards, as in SFML).
    static Sides localCollisionBox(const hitbox::GameObject& object);

    // Task 1: the collision box in world coordinates: the local box moved, scaled and
    // rotated with the object; when rotated, the smallest upright box around it.
    static Sides worldBox(const hitbox::GameObject& object);
    // Task 2: do the two objects' world boxes overlap (touching is not overlapping)?
    static bool checkBoundingBox(hitbox::GameObject* first, hitbox::GameObject* second);
    // Task 3: is a world point strictly inside the object's world box?
    static bool checkBoundingBox(hitbox::GameObject* object, sf::Vector2f point);
    // Task 4: the circle inscribed in the collision box (centre of the box, radius half
    // its shorter side, after scaling), and do two objects' circles overlap?
    static WorldCircle worldCircle(const hitbox::GameObject& object);
    static bool checkBoundingCircle(hitbox::GameObject* first, hitbox::GameObject* second);
    // Task 5: the first object's circle against the second object's world box.
    static bool checkCircleBox(hitbox::GameObject* circleObject, hitbox::GameObject* boxObject);
};
