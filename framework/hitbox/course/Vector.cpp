#include "hitbox/course/Vector.h"

#include <cmath>

float Vector::magnitude(sf::Vector2f vector)
{
    // Pythagoras, sqrt(x * x + y * y). std::hypot computes the same without x * x
    // underflowing to 0 for tiny vectors (or overflowing for huge ones).
    return std::hypot(vector.x, vector.y);
}

sf::Vector2f Vector::normalise(sf::Vector2f vector)
{
    const float length = magnitude(vector);
    if (length == 0.f)
        return vector;
    return vector / length;
}

float Vector::dot(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.x + a.y * b.y;
}
