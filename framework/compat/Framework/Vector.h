// Framework/Vector.h - the course's helpers for sf::Vector2f that SFML leaves out: length,
// unit vector, dot; Hitbox's own maths (hitbox/geometry/Vec2.h) under the course's names.
//
// The course's old framework had these as static functions (Vector::normalise, later
// VectorHelper::normalise); both names work (see VectorHelper.h). SFML's graphics and
// <cmath> come along, as they did in the old header.
#pragma once

#include <SFML/Graphics.hpp>
#include <SFML/System/Vector2.hpp>
#include <cmath>

class Vector
{
public:
    // Every function is static: call Vector::magnitude(v) directly. Old lab code also makes
    // a Vector object or derives from Vector; both still work.

    // The length of the vector, in the vector's units (pixels, pixels per second...).
    static float magnitude(sf::Vector2f vector);
    // The vector scaled to length 1, pointing the same way. A zero vector has no direction:
    // it is returned unchanged, (0, 0), so "move along normalise(v) * speed" stands still.
    static sf::Vector2f normalise(sf::Vector2f vector);
    // a.x * b.x + a.y * b.y: positive when the two point the same way, zero when they are
    // at right angles, negative when they point apart.
    static float dot(sf::Vector2f a, sf::Vector2f b);
};
