#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/BlendMode.hpp>
#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/PrimitiveType.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Texture.hpp>
#include <SFML/Graphics/Vertex.hpp>

#include <algorithm>

namespace hitbox
{

sf::RenderStates renderStatesFor(bool allOpaque)
{
    return allOpaque ? sf::RenderStates(sf::BlendNone) : sf::RenderStates::Default;
}

// Whole squares per draw call, a trick for Mesa's llvmpipe, the software renderer of Linux
// machines without a graphics card (virtual machines, Xvfb). llvmpipe fills two triangles that
// make an axis-aligned rectangle as one rectangle, skipping its per-pixel edge tests, but only
// in a piece of a draw call whose vertex count is a multiple of six (Mesa's lp_setup_vbuf.c).
// It cuts long calls into pieces of 4,096 vertices, which never are; ours always are. Lab 8's
// 10,000 balls drew 31-43 % more frames a second; a few edge pixels may move
// (docs/performance.md, "Ninth round").
static_assert(verticesPerDrawCall % 6 == 0, "whole squares of two triangles each");
static_assert(verticesPerDrawCall <= 4096, "no longer than llvmpipe's own pieces");

void drawTriangles(sf::RenderTarget& target, const sf::Vertex* vertices, std::size_t count,
                   const sf::RenderStates& states)
{
    for (std::size_t first = 0; first < count; first += verticesPerDrawCall)
        target.draw(vertices + first, std::min(verticesPerDrawCall, count - first),
                    sf::PrimitiveType::Triangles, states);
}

#if SFML_VERSION_MAJOR >= 3

sf::Text makeText(const sf::Font& font, const sf::String& string, unsigned characterSize)
{
    return sf::Text(font, string, characterSize);
}

bool openFont(sf::Font& font, const std::string& path)
{
    return font.openFromFile(path);
}

sf::VideoMode videoMode(unsigned width, unsigned height)
{
    return sf::VideoMode({width, height});
}

sf::Vector2u videoModeSize(const sf::VideoMode& mode)
{
    return mode.size;
}

bool makeCanvas(sf::RenderTexture& canvas, unsigned width, unsigned height)
{
    return canvas.resize({width, height});
}

sf::Image makeImage(unsigned width, unsigned height, const std::uint8_t* pixels)
{
    return sf::Image({width, height}, pixels);
}

sf::Image captureWindow(const sf::RenderWindow& window)
{
    sf::Texture capture(window.getSize());
    capture.update(window);
    return capture.copyToImage();
}

void setRotationDegrees(sf::Transformable& shape, float degrees)
{
    shape.setRotation(sf::degrees(degrees));
}

float getRotationDegrees(const sf::Transformable& shape)
{
    return shape.getRotation().asDegrees();
}

sf::Vector2f rectPosition(const sf::FloatRect& rect)
{
    return rect.position;
}

sf::Vector2f rectSize(const sf::FloatRect& rect)
{
    return rect.size;
}

sf::Vector2i rectPosition(const sf::IntRect& rect)
{
    return rect.position;
}

sf::Vector2i rectSize(const sf::IntRect& rect)
{
    return rect.size;
}

#else

sf::Text makeText(const sf::Font& font, const sf::String& string, unsigned characterSize)
{
    return sf::Text(string, font, characterSize);
}

bool openFont(sf::Font& font, const std::string& path)
{
    return font.loadFromFile(path);
}

sf::VideoMode videoMode(unsigned width, unsigned height)
{
    return sf::VideoMode(width, height);
}

sf::Vector2u videoModeSize(const sf::VideoMode& mode)
{
    return {mode.width, mode.height};
}

bool makeCanvas(sf::RenderTexture& canvas, unsigned width, unsigned height)
{
    return canvas.create(width, height);
}

sf::Image makeImage(unsigned width, unsigned height, const std::uint8_t* pixels)
{
    sf::Image image;
    image.create(width, height, pixels);
    return image;
}

sf::Image captureWindow(const sf::RenderWindow& window)
{
    sf::Texture capture;
    if (!capture.create(window.getSize().x, window.getSize().y))
        return {};
    capture.update(window);
    return capture.copyToImage();
}

void setRotationDegrees(sf::Transformable& shape, float degrees)
{
    shape.setRotation(degrees);
}

float getRotationDegrees(const sf::Transformable& shape)
{
    return shape.getRotation();
}

sf::Vector2f rectPosition(const sf::FloatRect& rect)
{
    return {rect.left, rect.top};
}

sf::Vector2f rectSize(const sf::FloatRect& rect)
{
    return {rect.width, rect.height};
}

sf::Vector2i rectPosition(const sf::IntRect& rect)
{
    return {rect.left, rect.top};
}

sf::Vector2i rectSize(const sf::IntRect& rect)
{
    return {rect.width, rect.height};
}

#endif

} // namespace hitbox
