// Graphics.h - drawing calls whose form differs between SFML 2 and SFML 3, one helper each;
// and two ways of drawing that cost a software renderer less (renderStatesFor, drawTriangles).
//
// Where both versions accept the same call (setPosition({x, y}), sf::FloatRect({x, y},
// {w, h}), sf::PrimitiveType::Triangles, sf::Keyboard::Key::A), use that call directly.
#pragma once

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/RenderStates.hpp>
#include <SFML/Graphics/Text.hpp>
#include <SFML/Graphics/Transformable.hpp>
#include <SFML/Graphics/Vertex.hpp> // not declared ahead: a class in SFML 2, a struct in SFML 3
                                    // (the mismatch is MSVC's warning C4099)
#include <SFML/Window/VideoMode.hpp>

#include <cstddef>
#include <cstdint>
#include <string>

namespace sf
{
class Image;
class RenderTarget;
class RenderTexture;
class RenderWindow;
} // namespace sf

namespace hitbox
{

// A text to draw. SFML 3's sf::Text needs its font when it is made, SFML 2's takes
// (string, font, size) in another order.
[[nodiscard]] sf::Text makeText(const sf::Font& font, const sf::String& string,
                                unsigned characterSize);

// Loads a font file; false when it cannot (SFML 2: loadFromFile, SFML 3: openFromFile).
[[nodiscard]] bool openFont(sf::Font& font, const std::string& path);

// A window mode of `width` x `height` pixels.
[[nodiscard]] sf::VideoMode videoMode(unsigned width, unsigned height);

// A window mode's size in pixels (SFML 3: mode.size, SFML 2: mode.width and mode.height).
[[nodiscard]] sf::Vector2u videoModeSize(const sf::VideoMode& mode);

// Makes `canvas` `width` x `height` pixels; false when the graphics driver cannot.
[[nodiscard]] bool makeCanvas(sf::RenderTexture& canvas, unsigned width, unsigned height);

// A `width` x `height` image from its pixels: red, green, blue and alpha bytes, row by row.
[[nodiscard]] sf::Image makeImage(unsigned width, unsigned height, const std::uint8_t* pixels);

// What `window` shows now, as an image (for screenshots).
[[nodiscard]] sf::Image captureWindow(const sf::RenderWindow& window);

// How to draw vertices whose colours are all opaque (`allOpaque`: every alpha is 255) or not.
// Opaque colours skip blending: blending an opaque colour writes that same colour, so the
// pixels do not change, and a software renderer need not read each one back first. Anything
// see-through is blended as usual (SFML's default, sf::BlendAlpha).
[[nodiscard]] sf::RenderStates renderStatesFor(bool allOpaque);

// How many vertices drawTriangles hands the renderer in one draw call: 682 squares of two
// triangles (why: Graphics.cpp, "whole squares per draw call").
inline constexpr std::size_t verticesPerDrawCall = 4092;

// Draws `count` vertices as sf::PrimitiveType::Triangles (three a triangle), in calls of
// verticesPerDrawCall vertices: the picture of one call, faster on Mesa's software renderer. A
// count of 0 draws nothing.
void drawTriangles(sf::RenderTarget& target, const sf::Vertex* vertices, std::size_t count,
                   const sf::RenderStates& states);

// Rotation in degrees, clockwise (SFML 3 uses sf::Angle, SFML 2 a float in degrees).
void setRotationDegrees(sf::Transformable& shape, float degrees);
[[nodiscard]] float getRotationDegrees(const sf::Transformable& shape);

// A rectangle's corner and size (SFML 3: position/size, SFML 2: left/top/width/height).
[[nodiscard]] sf::Vector2f rectPosition(const sf::FloatRect& rect);
[[nodiscard]] sf::Vector2f rectSize(const sf::FloatRect& rect);
[[nodiscard]] sf::Vector2i rectPosition(const sf::IntRect& rect);
[[nodiscard]] sf::Vector2i rectSize(const sf::IntRect& rect);

} // namespace hitbox
