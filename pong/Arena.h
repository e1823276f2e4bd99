// Arena.h - the playing field: its size and the top and bottom walls.
//
// The walls are thick boxes that reach far beyond the screen (up, down and sideways), so a
// ball can never get round or behind them, however fast it goes. Only the strip that shows
// is drawn. The left and right sides are open: leaving there scores a point.
#pragma once

#include "hitbox/app/Level.h"

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>

struct Arena
{
    sf::Vector2f size = hitbox::defaultWorldSize; // the whole world, in pixels
    float bottomMargin = 24.f;  // the framework's help line sits here, below the wall
    float wallThickness = 12.f; // the part of each wall that is drawn

    // The first and last y the ball and the paddles may occupy.
    float playTop() const;
    float playBottom() const;
    float centerX() const;
    float centerY() const;

    // The walls as collision boxes (huge, see above) and as the strips to draw.
    sf::FloatRect topWall() const;
    sf::FloatRect bottomWall() const;
    sf::FloatRect topWallStrip() const;
    sf::FloatRect bottomWallStrip() const;
};
