// VectorMath.h - the few vector operations the geometry functions share: dot and cross
// products, length, and a unit vector with a stated answer for the zero vector.
#pragma once

#include <SFML/System/Vector2.hpp>

#include <cmath>

namespace hitbox
{

// a.x * b.x + a.y * b.y: how far `a` goes along `b` (times |b|).
inline float dot(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.x + a.y * b.y;
}

// The z of the 3D cross product: > 0 when `b` turns clockwise from `a` on screen (y down).
inline float cross(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.y - a.y * b.x;
}

inline float lengthOf(sf::Vector2f vector)
{
    return static_cast<float>(std::hypot(double(vector.x), double(vector.y)));
}

// `vector` scaled to length 1, or `fallback` when it has no direction (zero, NaN, infinite).
inline sf::Vector2f unitOr(sf::Vector2f vector, sf::Vector2f fallback)
{
    const double length = std::hypot(double(vector.x), double(vector.y));
    if (!(length > 0.0) || !std::isfinite(length))
        return fallback;
    return {static_cast<float>(vector.x / length), static_cast<float>(vector.y / length)};
}

// The vector turned a quarter turn (x, y) -> (-y, x): perpendicular, same length.
inline sf::Vector2f perpendicular(sf::Vector2f vector)
{
    return {-vector.y, vector.x};
}

} // namespace hitbox
