// The sfml/ layer: Hitbox's plain values to SFML's and back, and the calls whose form
// differs between SFML 2 and 3, each giving the same answer on both (no window needed).
#include "support/SfmlPrinters.h"

#include "hitbox/sfml/Conversions.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/BlendMode.hpp>
#include <SFML/Graphics/Image.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

TEST(SfmlConversions, AVectorCrossesBothWaysUnchanged)
{
    const hitbox::Vec2 vector{-3.5f, 1e6f};
    EXPECT_EQ(hitbox::toVec2(hitbox::toSfml(vector)), vector);
    EXPECT_EQ(hitbox::toVec2(sf::Vector2i(-4, 7)), hitbox::Vec2(-4.f, 7.f));
    EXPECT_EQ(hitbox::toVec2(sf::Vector2u(800u, 600u)), hitbox::Vec2(800.f, 600.f));
}

TEST(SfmlConversions, ABoxKeepsItsCornerAndSizeInAnSfmlRect)
{
    const hitbox::Box box{10.f, -20.f, 30.f, 40.f};
    const sf::FloatRect rect = hitbox::toSfml(box);
    EXPECT_EQ(hitbox::rectPosition(rect), sf::Vector2f(10.f, -20.f));
    EXPECT_EQ(hitbox::rectSize(rect), sf::Vector2f(30.f, 40.f));
    EXPECT_EQ(hitbox::toBox(rect), box);
}

TEST(SfmlGraphics, OnlyOpaqueColoursSkipBlending)
{
    // Opaque: drawn as they are, no blending (the same pixels, cheaper to draw).
    EXPECT_EQ(hitbox::renderStatesFor(true).blendMode, sf::BlendNone);
    // Anything see-through: SFML's usual alpha blending, so it still shows what lies beneath.
    EXPECT_EQ(hitbox::renderStatesFor(false).blendMode, sf::BlendAlpha);
}

TEST(SfmlGraphics, RotationIsInDegreesClockwiseOnBothVersions)
{
    sf::RectangleShape shape;
    hitbox::setRotationDegrees(shape, 90.f);
    EXPECT_FLOAT_EQ(hitbox::getRotationDegrees(shape), 90.f);
    // Turned a quarter clockwise (y down), the x axis points down the screen.
    const sf::Vector2f turned = shape.getTransform().transformPoint({1.f, 0.f});
    EXPECT_NEAR(turned.x, 0.f, 1e-6f);
    EXPECT_NEAR(turned.y, 1.f, 1e-6f);
}

TEST(SfmlGraphics, AnImageIsMadeFromItsPixelsRowByRow)
{
    // Two by one: a red pixel, then a half-transparent blue one.
    const std::vector<std::uint8_t> pixels{255, 0, 0, 255, 0, 0, 255, 128};
    const sf::Image image = hitbox::makeImage(2, 1, pixels.data());
    EXPECT_EQ(image.getSize(), sf::Vector2u(2u, 1u));
    // (getPixel takes (x, y) in SFML 2 and a vector in 3: the bytes are the same on both.)
    EXPECT_EQ(std::vector<std::uint8_t>(image.getPixelsPtr(), image.getPixelsPtr() + 8), pixels);
    EXPECT_EQ(hitbox::videoModeSize(hitbox::videoMode(640, 480)), sf::Vector2u(640u, 480u));
}
