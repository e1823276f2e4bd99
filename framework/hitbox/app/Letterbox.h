// Letterbox.h - the whole world on any screen or picture, never stretched: the window's
// viewport (bars where the shapes differ) and a --screenshot picture's size.
#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>

namespace hitbox
{

// The longest side of a --screenshot picture: a world larger than this (or than the
// graphics driver's largest texture) is drawn shrunk to fit, whole.
constexpr unsigned maxPictureSide = 4096;

// `size` in whole pixels, shrunk (never grown, never stretched) to fit inside `limit`;
// at least 1 x 1. A zero, negative or NaN side counts as 1 pixel.
[[nodiscard]] sf::Vector2u fitInside(sf::Vector2f size, sf::Vector2u limit);

// The part of a window, as fractions of its size (a view's viewport), that shows a world
// of `worldSize` as large as possible without stretching: bars fill the rest (letterbox).
[[nodiscard]] sf::FloatRect letterboxViewport(sf::Vector2u windowSize, sf::Vector2f worldSize);

} // namespace hitbox
