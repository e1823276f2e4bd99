// Helpers of lab 3's grading tests: crates made without task 1, squares stepped and bounced
// apart without task 2, and how far two boxes overlap. Both the grading tests
// (SquaresGradingTests.cpp) and their hidden variants use them: one home for each.
#pragma once

#include "Square.h"

#include "hitbox/app/Loop.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/Color.hpp>
#include <SFML/System/Vector2.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace squareschecks
{

// How far two boxes may overlap at the end of a step: the response separates them in the
// step they meet, so only rounding is left.
inline constexpr float overlapTolerance = 0.5f;
// The see-through margin on each side of the crate: what hangs over a wall the crate touches.
inline constexpr float margin = (spriteSize - crateSize) / 2.f;

// A square with the crate's collision box, set here as task 1 sets it: the tests of tasks 2
// and 3 need no task 1 (one mistake costs one task).
inline Square crate(sf::Vector2f center, sf::Vector2f velocity)
{
    Square square(center, velocity, sf::Color::White);
    square.setCollisionBox(-crateSize / 2.f, -crateSize / 2.f, crateSize, crateSize);
    return square;
}

// How many fixed steps make `seconds`: tests give their times in seconds, the loop runs steps.
inline int stepsFor(float seconds)
{
    return static_cast<int>(seconds * hitbox::stepsPerSecond);
}

// Task 3's tests: every step the test moves the squares itself (no task 2), keeps them in
// `world` if it has one (a crowd needs walls to stay a crowd), then calls bounceApart on
// every pair, the way SquaresLevel::update does.
inline void stepApart(std::vector<Square>& squares, int steps, sf::Vector2f world = {})
{
    for (int step = 0; step < steps; ++step)
    {
        for (Square& square : squares)
        {
            square.move(square.getVelocity() * hitbox::stepSeconds);
            if (world.x <= 0.f)
                continue;
            const hitbox::Box box = hitbox::toBox(square.getCollisionBox());
            sf::Vector2f velocity = square.getVelocity();
            if (box.left < 0.f || box.left + box.width > world.x)
            {
                square.move({box.left < 0.f ? -box.left : world.x - (box.left + box.width), 0.f});
                velocity.x = box.left < 0.f ? std::abs(velocity.x) : -std::abs(velocity.x);
            }
            if (box.top < 0.f || box.top + box.height > world.y)
            {
                square.move({0.f, box.top < 0.f ? -box.top : world.y - (box.top + box.height)});
                velocity.y = box.top < 0.f ? std::abs(velocity.y) : -std::abs(velocity.y);
            }
            square.setVelocity(velocity);
        }
        for (std::size_t i = 0; i < squares.size(); ++i)
            for (std::size_t j = i + 1; j < squares.size(); ++j)
                bounceApart(squares[i], squares[j]);
    }
}

// How far two boxes overlap along the axis where they overlap least (0 if they do not): how
// deep one crate got into another, to hold against overlapTolerance.
inline float overlapOf(const hitbox::Box& a, const hitbox::Box& b)
{
    const float x = std::min(a.left + a.width, b.left + b.width) - std::max(a.left, b.left);
    const float y = std::min(a.top + a.height, b.top + b.height) - std::max(a.top, b.top);
    return std::max(0.f, std::min(x, y));
}

} // namespace squareschecks
