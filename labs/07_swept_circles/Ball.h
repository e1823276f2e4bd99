// Ball.h - one pool ball: a circle, a velocity and a colour. Plain data, so a test can build
// any table it likes.
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <SFML/Graphics/Color.hpp>

struct Ball
{
    hitbox::Circle shape;  // centre and radius in pixels
    hitbox::Vec2 velocity; // pixels per second
    sf::Color color = sf::Color::White;

    // Move along the velocity for `seconds`.
    void advance(float seconds) { shape.center += velocity * seconds; }
};
