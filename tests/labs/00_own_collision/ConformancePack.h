// ConformancePack.h - the rules MyCollision must follow, as checks a test can run on any
// numbers. The visible tests (ConformanceTests.cpp) run them at one place and size; the
// hidden variants a grader keeps run the same rules at others, so a class written to pass
// only the visible numbers fails there.
//
// Every check compares with the framework's Collision class or with numbers worked out by
// hand, and a failure says which rule was broken and prints both objects.
#pragma once

#include <SFML/System/Vector2.hpp>

namespace conformance
{
// Where and how large a variant's cases are: every fixed case is moved by `offset` and
// its lengths multiplied by `unit` (a power of two, so that touching stays exact), and the
// random cases use `seed`.
struct Variant
{
    sf::Vector2f offset;
    float unit = 1.f;
    unsigned seed = 1;
};

// Task 1: worldBox for moved origins, scales (mirrored too), rotations, collision boxes
// smaller than the picture or spanning backwards, zero sizes and NaN; then random objects
// against the framework's GameObject::getCollisionBox.
void checkWorldBox(const Variant& variant);
// Task 2: box against box: touching on each side and at each corner never collides, a
// hair's overlap does, crossing boxes, boxes inside boxes, zero-size boxes, NaN, null,
// dead and the same object twice; both argument orders; then random boxes against
// Collision::checkBoundingBox.
void checkBoxAgainstBox(const Variant& variant);
// Task 3: a point in a box: on each edge and corner it is outside; NaN; zero-size boxes;
// then random points against Collision::checkBoundingBox(object, point).
void checkPointInBox(const Variant& variant);
// Task 4: worldCircle (from the collision box, after scaling, never from the picture's
// width) and checkBoundingCircle: touching along x, y and a diagonal never collides; one
// inside another does; NaN; both argument orders; then random objects against
// Collision::checkBoundingCircle.
void checkBoundingCircle(const Variant& variant);
// Task 5: circle against box: touching each side, near a corner (inside the circle's
// square but outside the circle), centre inside, a zero-radius circle, NaN, the argument
// order (circle first); then random objects against Collision::checkCircleBox.
void checkCircleAgainstBox(const Variant& variant);
} // namespace conformance
