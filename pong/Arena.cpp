#include "Arena.h"

namespace
{
// How far the wall boxes reach beyond the screen, in pixels. Far more than the ball can
// travel in one step at any sane speed; the sweep does not depend on it, it only keeps the
// walls closed at the corners of the screen.
const float wallReach = 10000.f;
} // namespace

float Arena::playTop() const
{
    return wallThickness;
}

float Arena::playBottom() const
{
    return size.y - bottomMargin - wallThickness;
}

float Arena::centerX() const
{
    return size.x / 2.f;
}

float Arena::centerY() const
{
    return (playTop() + playBottom()) / 2.f;
}

sf::FloatRect Arena::topWall() const
{
    return sf::FloatRect({-wallReach, playTop() - wallReach},
                         {size.x + 2.f * wallReach, wallReach});
}

sf::FloatRect Arena::bottomWall() const
{
    return sf::FloatRect({-wallReach, playBottom()}, {size.x + 2.f * wallReach, wallReach});
}

sf::FloatRect Arena::topWallStrip() const
{
    return sf::FloatRect({0.f, 0.f}, {size.x, wallThickness});
}

sf::FloatRect Arena::bottomWallStrip() const
{
    return sf::FloatRect({0.f, playBottom()}, {size.x, wallThickness});
}
