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

namespace
{
// Whole squares per draw call. Mesa's llvmpipe, the software renderer of Linux machines with
// no graphics card (virtual machines, Xvfb), fills a square made of two triangles as one
// rectangle, without testing each 4x4 block of pixels against its edges, when it finds the
// six vertices together in the piece of a draw call it is working on. It cuts a call into
// pieces of 4,096 vertices, which is not a whole number of squares, so after the first piece
// every square would be split and drawn as two triangles. Cutting first, into pieces of 682
// squares, keeps them whole (Mesa's sources: draw_pt_fetch_shade_pipeline_llvm.c makes the
// pieces, lp_setup_vbuf.c finds the rectangles). Lab 8's 10,000 balls, squares at that size,
// drew 79-83 frames a second with --debug under Xvfb instead of 56-63 (docs/performance.md,
// "Ninth round"). The rectangles may round an edge to the next pixel where the triangles did
// not: in that window, paused at step 120, 8 of the 1,310,720 pixels changed; the sheet
// pictures, drawn into a texture, did not change at all. A graphics card draws what it drew
// before, and 15 calls instead of 1 cost it nothing it would notice.
const std::size_t verticesPerDrawCall = 4092;
static_assert(verticesPerDrawCall % 6 == 0, "whole squares of two triangles");
static_assert(verticesPerDrawCall <= 4096, "no longer than llvmpipe's own pieces");
} // namespace

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
