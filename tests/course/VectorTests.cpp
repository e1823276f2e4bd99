// Vector / VectorHelper: the course's static vector helpers (length, unit vector, dot).
#include "support/SfmlPrinters.h"

#include "Framework/Vector.h"
#include "Framework/VectorHelper.h"

#include <gtest/gtest.h>

#include <cmath>

TEST(Vector, MagnitudeIsPythagoras)
{
    EXPECT_FLOAT_EQ(Vector::magnitude({3.f, 4.f}), 5.f);
    EXPECT_FLOAT_EQ(Vector::magnitude({-3.f, -4.f}), 5.f);
    EXPECT_FLOAT_EQ(Vector::magnitude({0.f, 0.f}), 0.f);
}

TEST(Vector, NormaliseKeepsTheDirectionAtLengthOne)
{
    const sf::Vector2f unit = Vector::normalise({30.f, -40.f});
    EXPECT_FLOAT_EQ(unit.x, 0.6f);
    EXPECT_FLOAT_EQ(unit.y, -0.8f);
    EXPECT_FLOAT_EQ(Vector::magnitude(unit), 1.f);
}

TEST(Vector, NormaliseOfAZeroVectorIsZeroNotNaN)
{
    // A ball with no velocity has no direction: moving along it must keep it still.
    const sf::Vector2f unit = Vector::normalise({0.f, 0.f});
    EXPECT_EQ(unit, sf::Vector2f(0.f, 0.f));
    EXPECT_FALSE(std::isnan(unit.x) || std::isnan(unit.y));
}

TEST(Vector, NormaliseOfATinyVectorIsStillUnitLength)
{
    const sf::Vector2f unit = Vector::normalise({1e-20f, 0.f});
    EXPECT_FLOAT_EQ(unit.x, 1.f);
    EXPECT_FLOAT_EQ(unit.y, 0.f);
}

TEST(Vector, DotSaysWhetherTwoDirectionsAgree)
{
    EXPECT_FLOAT_EQ(Vector::dot({1.f, 2.f}, {3.f, 4.f}), 11.f);
    EXPECT_GT(Vector::dot({1.f, 0.f}, {5.f, 1.f}), 0.f);       // same way
    EXPECT_FLOAT_EQ(Vector::dot({1.f, 0.f}, {0.f, 7.f}), 0.f); // right angle
    EXPECT_LT(Vector::dot({1.f, 0.f}, {-2.f, 1.f}), 0.f);      // apart
}

TEST(VectorHelper, IsTheSameHelpersUnderTheLaterName)
{
    EXPECT_FLOAT_EQ(VectorHelper::magnitude({6.f, 8.f}), 10.f);
    EXPECT_EQ(VectorHelper::normalise({0.f, -2.f}), sf::Vector2f(0.f, -1.f));
    EXPECT_FLOAT_EQ(VectorHelper::dot({2.f, 0.f}, {3.f, 5.f}), 6.f);
}
