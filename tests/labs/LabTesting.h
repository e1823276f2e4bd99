// LabTesting.h - small helpers shared by the labs' grading tests.
#pragma once

#include "support/SfmlPrinters.h"

#include <SFML/System/Vector2.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

namespace labtesting
{

// The geometry helpers for an SFML rectangle (the boxes that GameObjects report).
inline sf::Vector2f centerOf(const sf::FloatRect& rect)
{
    return hitbox::toSfml(hitbox::centerOf(hitbox::toBox(rect)));
}
inline float rightOf(const sf::FloatRect& rect)
{
    return hitbox::rightOf(hitbox::toBox(rect));
}
inline float bottomOf(const sf::FloatRect& rect)
{
    return hitbox::bottomOf(hitbox::toBox(rect));
}
// "(x, y)" for failure messages.
inline std::string text(sf::Vector2f vector)
{
    return testing::PrintToString(vector);
}

inline testing::AssertionResult vectorsNear(const char* actualText, const char* expectedText,
                                            const char*, sf::Vector2f actual, sf::Vector2f expected,
                                            float tolerance)
{
    if (std::abs(actual.x - expected.x) <= tolerance &&
        std::abs(actual.y - expected.y) <= tolerance)
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << actualText << " is " << text(actual) << ", expected " << expectedText << " = "
           << text(expected) << " (within " << tolerance << " pixels)";
}

// Where the i-th of a crowd of columns x rows objects starts, and how it moves: spread evenly
// over the world, each flying off at `speed` in its own direction (successive objects the
// golden angle apart, so no two directions repeat).
struct CrowdStart
{
    sf::Vector2f position;
    sf::Vector2f velocity;
};
inline CrowdStart crowdStart(int i, int columns, int rows, sf::Vector2f world, float speed)
{
    const float direction = 2.39996f * static_cast<float>(i); // the golden angle, in radians
    return {{world.x * static_cast<float>(i % columns + 1) / static_cast<float>(columns + 1),
             world.y * static_cast<float>(i / columns + 1) / static_cast<float>(rows + 1)},
            speed * sf::Vector2f(std::cos(direction), std::sin(direction))};
}
} // namespace labtesting

// Both coordinates of two sf::Vector2f within `tolerance` of each other.
#define EXPECT_VEC_NEAR(actual, expected, tolerance)                                               \
    EXPECT_PRED_FORMAT3(labtesting::vectorsNear, actual, expected, tolerance)
