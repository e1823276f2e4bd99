// PoolChecks.h - what lab 7's tests need to set up a table: balls of one radius and the box
// a ball's centre must stay within. Both the grading tests (PoolGradingTests.cpp) and their
// hidden variants (tests/labs-hidden/07_swept_circles/) use it.
#pragma once

#include "Ball.h"

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Vec2.h"

#include <SFML/Graphics/Color.hpp>

namespace poolchecks
{

// Every ball the tests place has this radius (the lab's own balls are 14 px too).
inline constexpr float radius = 14.f;

// A ball of the tests' radius, so a scene states only where each ball is and how it moves.
inline Ball ballAt(hitbox::Vec2 center, hitbox::Vec2 velocity = {0.f, 0.f})
{
    return {{center, radius}, velocity, sf::Color::White};
}

// Where a ball's centre may be on `table`: a centre outside it means the ball sank into or
// went through a cushion (a hair of slack for rounding at the moment of touching).
inline hitbox::Box centreBounds(const hitbox::Box& table)
{
    return {table.left + radius - 0.01f, table.top + radius - 0.01f,
            table.width - 2.f * radius + 0.02f, table.height - 2.f * radius + 0.02f};
}

} // namespace poolchecks
