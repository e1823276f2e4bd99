// Lab 2's hints are written inside Ball's functions (Ball.cpp).
#pragma once
#include "Ball.h"

#include <SFML/System/Vector2.hpp>
#include <cmath>

struct HintScope : Ball
{
    void hints();
    float x; // a coordinate of the ball's position
    float radius;
    sf::Vector2f worldSize; // Ball::worldSize (private: the hints are inside Ball)
    sf::Vector2f velocity;
};
