#include "hitbox/geometry/Shapes.h"

#include <cmath>

namespace hitbox
{

sf::Vector2f centerOf(const sf::FloatRect& box)
{
    return {box.left + box.width / 2.f, box.top + box.height / 2.f};
}

float rightOf(const sf::FloatRect& box)
{
    return box.left + box.width;
}

float bottomOf(const sf::FloatRect& box)
{
    return box.top + box.height;
}

bool isFinite(sf::Vector2f point)
{
    return std::isfinite(point.x) && std::isfinite(point.y);
}

bool isFinite(const sf::FloatRect& box)
{
    return std::isfinite(box.left) && std::isfinite(box.top) && std::isfinite(box.width) &&
           std::isfinite(box.height);
}

bool isFinite(const Circle& circle)
{
    return isFinite(circle.center) && std::isfinite(circle.radius);
}

} // namespace hitbox
