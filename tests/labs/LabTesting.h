// LabTesting.h - small helpers shared by the labs' grading tests.
#pragma once

#include "support/Printers.h"

#include <SFML/System/Vector2.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

namespace labtesting
{
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
} // namespace labtesting

// Both coordinates of two sf::Vector2f within `tolerance` of each other.
#define EXPECT_VEC_NEAR(actual, expected, tolerance)                                               \
    EXPECT_PRED_FORMAT3(labtesting::vectorsNear, actual, expected, tolerance)
