#include "SquaresLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>

namespace
{
const sf::Color crateColors[] = {{70, 120, 220}, {80, 190, 100}, {220, 120, 60}, {190, 90, 200},
                                 {220, 190, 60}, {70, 190, 190}, {210, 80, 90},  {170, 170, 170}};
} // namespace

SquaresLevel::SquaresLevel(int squareCount, unsigned seed) : random(seed)
{
    startWithTwoSquares();
    while (getSquareCount() < std::min(squareCount, maxSquares))
        addRandomSquare();
}

void SquaresLevel::startWithTwoSquares()
{
    removeAllSquares();
    const sf::Vector2f world = getWorldSize();
    addSquare({world.x * 0.2f, world.y / 2.f}, {squareSpeed, 0.f});
    addSquare({world.x * 0.8f, world.y / 2.f}, {-squareSpeed, 0.f});
}

void SquaresLevel::addRandomSquare()
{
    const sf::Vector2f world = getWorldSize();
    std::uniform_real_distribution<float> x(spriteSize / 2.f, world.x - spriteSize / 2.f);
    std::uniform_real_distribution<float> y(spriteSize / 2.f, world.y - spriteSize / 2.f);
    std::uniform_int_distribution<int> sign(0, 1);
    for (int attempt = 0; attempt < 100; ++attempt)
    {
        const sf::Vector2f center{x(random), y(random)};
        bool free = true;
        for (const Square& square : squares)
            free = free && (std::abs(square.getPosition().x - center.x) > spriteSize ||
                            std::abs(square.getPosition().y - center.y) > spriteSize);
        if (free)
        {
            // Diagonal, at squareSpeed in total: 1/sqrt(2) of it along each axis.
            const float along = squareSpeed * 0.7071068f;
            addSquare(center, {sign(random) ? along : -along, sign(random) ? along : -along});
            return;
        }
    }
}

void SquaresLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.isPressed(sf::Keyboard::Key::Space) && getSquareCount() < maxSquares)
        addRandomSquare();
    if (input.isPressed(sf::Keyboard::Key::R))
        startWithTwoSquares();
}

void SquaresLevel::update(float dt)
{
    for (Square& square : squares)
        square.update(dt);

    // Every pair once: square i against every square after it.
    for (std::size_t i = 0; i < squares.size(); ++i)
        for (std::size_t j = i + 1; j < squares.size(); ++j)
            bounceApart(squares[i], squares[j]);
}

void SquaresLevel::render(sf::RenderTarget& target) const
{
    for (const Square& square : squares)
    {
        // The picture: a see-through margin (drawn faintly, the way a paint program shows
        // transparent pixels) around a solid crate. The picture never changes: only the
        // collision box decides how the squares collide.
        const sf::Color color = square.getFillColor();
        sf::RectangleShape picture({spriteSize, spriteSize});
        picture.setOrigin({spriteSize / 2.f, spriteSize / 2.f});
        picture.setPosition(square.getPosition());
        picture.setFillColor(sf::Color(color.r, color.g, color.b, 45));
        picture.setOutlineThickness(-1.f);
        picture.setOutlineColor(sf::Color(color.r, color.g, color.b, 110));
        target.draw(picture);

        const float white = square.getFlash() * 0.6f;
        const auto mix = [white](std::uint8_t channel)
        { return static_cast<std::uint8_t>(channel + (255 - channel) * white); };
        sf::RectangleShape crate({crateSize, crateSize});
        crate.setOrigin({crateSize / 2.f, crateSize / 2.f});
        crate.setPosition(square.getPosition());
        crate.setFillColor(sf::Color(mix(color.r), mix(color.g), mix(color.b)));
        crate.setOutlineThickness(-5.f);
        crate.setOutlineColor(sf::Color(color.r / 2, color.g / 2, color.b / 2));
        target.draw(crate);
    }
}

void SquaresLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    for (const Square& square : squares)
        debug.objectBox(square, square.getFlash() > 0.f);
}

std::string SquaresLevel::getHelpText() const
{
    return "Space add a square   R two squares again";
}

std::string SquaresLevel::describeState() const
{
    int hits = 0;
    for (const Square& square : squares)
        hits += square.getHitCount();
    char text[120];
    std::snprintf(text, sizeof text, "%d squares, %d hits so far", getSquareCount(), hits);
    return text;
}

void SquaresLevel::removeAllSquares()
{
    squares.clear();
}

void SquaresLevel::addSquare(sf::Vector2f center, sf::Vector2f velocity)
{
    const int index = getSquareCount();
    squares.emplace_back(center, velocity, crateColors[index % std::size(crateColors)]);
    squares.back().setWorldSize(getWorldSize());
}

int SquaresLevel::getSquareCount() const
{
    return static_cast<int>(squares.size());
}

const Square& SquaresLevel::getSquare(int index) const
{
    return squares.at(static_cast<std::size_t>(index));
}
