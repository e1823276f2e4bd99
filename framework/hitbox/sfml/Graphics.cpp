#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/BlendMode.hpp>
#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/RenderTexture.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Texture.hpp>

namespace hitbox
{

sf::RenderStates renderStatesFor(bool allOpaque)
{
    return allOpaque ? sf::RenderStates(sf::BlendNone) : sf::RenderStates::Default;
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
