// Conversions.h - Hitbox's plain values (geometry/Vec2.h, geometry/Shapes.h) to SFML's types
// and back. The maths knows no SFML; this is the edge where the two meet, and one of the few
// places that knows which SFML version is installed (sf::Rect's fields differ: SFML 2 has
// left/top/width/height, SFML 3 has position and size).
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <SFML/Config.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>

namespace hitbox
{

[[nodiscard]] inline Vec2 toVec2(sf::Vector2f vector)
{
    return {vector.x, vector.y};
}
// Whole-number vectors (mouse positions, window sizes) as pixels.
[[nodiscard]] inline Vec2 toVec2(sf::Vector2i vector)
{
    return {static_cast<float>(vector.x), static_cast<float>(vector.y)};
}
[[nodiscard]] inline Vec2 toVec2(sf::Vector2u vector)
{
    return {static_cast<float>(vector.x), static_cast<float>(vector.y)};
}

[[nodiscard]] inline sf::Vector2f toSfml(Vec2 vector)
{
    return {vector.x, vector.y};
}

[[nodiscard]] inline Box toBox(const sf::FloatRect& rect)
{
#if SFML_VERSION_MAJOR >= 3
    return {rect.position.x, rect.position.y, rect.size.x, rect.size.y};
#else
    return {rect.left, rect.top, rect.width, rect.height};
#endif
}

[[nodiscard]] inline sf::FloatRect toSfml(const Box& box)
{
    return sf::FloatRect({box.left, box.top}, {box.width, box.height});
}

} // namespace hitbox
