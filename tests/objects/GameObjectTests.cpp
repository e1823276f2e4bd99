// GameObject: the collision box measured from the origin point, following the shape until
// set, world space under move/scale/rotation; the bounding circle; the course API's flags.
#include "support/SfmlPrinters.h"

#include "hitbox/objects/GameObject.h"
#include "hitbox/sfml/Graphics.h"

#include <gtest/gtest.h>

namespace
{

void expectBoxNear(const sf::FloatRect& actualRect, const hitbox::Box& expected)
{
    const hitbox::Box actual = hitbox::toBox(actualRect);
    EXPECT_NEAR(actual.left, expected.left, 1e-3f) << ::testing::PrintToString(actualRect);
    EXPECT_NEAR(actual.top, expected.top, 1e-3f) << ::testing::PrintToString(actualRect);
    EXPECT_NEAR(actual.width, expected.width, 1e-3f) << ::testing::PrintToString(actualRect);
    EXPECT_NEAR(actual.height, expected.height, 1e-3f) << ::testing::PrintToString(actualRect);
}

} // namespace

TEST(GameObject, NewObjectIsAliveColliderAndStill)
{
    hitbox::GameObject object;
    EXPECT_TRUE(object.isAlive());
    EXPECT_TRUE(object.isCollider());
    EXPECT_EQ(object.getVelocity(), sf::Vector2f(0.f, 0.f));
}

TEST(GameObject, VelocityBothWays)
{
    hitbox::GameObject object;
    object.setVelocity(3.f, -4.f);
    EXPECT_EQ(object.getVelocity(), sf::Vector2f(3.f, -4.f));
    object.setVelocity(sf::Vector2f(1.f, 2.f));
    EXPECT_EQ(object.getVelocity(), sf::Vector2f(1.f, 2.f));
}

TEST(GameObject, UnsetBoxIsTheWholeShapeAndFollowsSizeAndOrigin)
{
    hitbox::GameObject object;
    object.setSize({40.f, 20.f});
    object.setPosition({100.f, 50.f});
    expectBoxNear(object.getCollisionBox(), {100.f, 50.f, 40.f, 20.f});
    object.setOrigin({20.f, 10.f});
    expectBoxNear(object.getCollisionBox(), {80.f, 40.f, 40.f, 20.f});
    object.setSize({60.f, 30.f});
    expectBoxNear(object.getCollisionBox(), {80.f, 40.f, 60.f, 30.f});
}

TEST(GameObject, BoxIsMeasuredFromTheOriginPoint)
{
    // The course's pattern: centre origin, box from -w/2, -h/2 covers the whole shape.
    hitbox::GameObject object;
    object.setSize({32.f, 32.f});
    object.setOrigin({16.f, 16.f});
    object.setCollisionBox(-16.f, -16.f, 32.f, 32.f);
    object.setPosition({200.f, 100.f});
    expectBoxNear(object.getCollisionBox(), {184.f, 84.f, 32.f, 32.f});
    expectBoxNear(object.getCollisionBox(), hitbox::toBox(object.getGlobalBounds()));
}

TEST(GameObject, LectureStyleBoxAtTopLeftOrigin)
{
    // square1.setCollisionBox(sf::FloatRect({0, 0}, {50, 50})) from the lecture.
    hitbox::GameObject square;
    square.setSize({50.f, 50.f});
    square.setCollisionBox(sf::FloatRect({0.f, 0.f}, {50.f, 50.f}));
    square.setPosition({0.f, 200.f});
    expectBoxNear(square.getCollisionBox(), {0.f, 200.f, 50.f, 50.f});
}

TEST(GameObject, SmallerBoxGivesAMargin)
{
    hitbox::GameObject object;
    object.setSize({50.f, 50.f});
    object.setCollisionBox(5.f, 10.f, 40.f, 30.f);
    object.setPosition({100.f, 100.f});
    expectBoxNear(object.getCollisionBox(), {105.f, 110.f, 40.f, 30.f});
}

TEST(GameObject, BoxScalesWithTheObject)
{
    hitbox::GameObject object;
    object.setSize({10.f, 10.f});
    object.setOrigin({5.f, 5.f});
    object.setPosition({100.f, 100.f});
    object.setScale({2.f, 3.f});
    expectBoxNear(object.getCollisionBox(), {90.f, 85.f, 20.f, 30.f});
    object.setScale({-2.f, 1.f}); // mirrored: still a box with a positive size
    expectBoxNear(object.getCollisionBox(), {90.f, 95.f, 20.f, 10.f});
}

TEST(GameObject, RotatedBoxIsTheEnclosingAxisAlignedBox)
{
    hitbox::GameObject object;
    object.setSize({20.f, 10.f});
    object.setOrigin({10.f, 5.f});
    object.setPosition({100.f, 100.f});
    hitbox::setRotationDegrees(object, 90.f);
    expectBoxNear(object.getCollisionBox(), {95.f, 90.f, 10.f, 20.f});
    hitbox::setRotationDegrees(object, 45.f);
    const float half = (20.f + 10.f) / 2.f * 0.70710678f; // half the diagonal spread
    expectBoxNear(object.getCollisionBox(), {100.f - half, 100.f - half, 2 * half, 2 * half});
}

TEST(GameObject, ClearCollisionBoxGoesBackToTheWholeShape)
{
    hitbox::GameObject object;
    object.setSize({50.f, 50.f});
    object.setCollisionBox(10.f, 10.f, 5.f, 5.f);
    object.clearCollisionBox();
    expectBoxNear(object.getCollisionBox(), {0.f, 0.f, 50.f, 50.f});
}

TEST(GameObject, DefaultCircleIsInscribedInTheCollisionBox)
{
    // The lecture took radius = width / 2 and the centre at the top-left: wrong for any
    // origin other than the corner. Hitbox uses the collision box.
    hitbox::GameObject ball;
    ball.setSize({40.f, 40.f});
    ball.setOrigin({20.f, 20.f});
    ball.setPosition({300.f, 200.f});
    const hitbox::Circle circle = ball.getBoundingCircle();
    EXPECT_EQ(circle.center, hitbox::Vec2(300.f, 200.f));
    EXPECT_FLOAT_EQ(circle.radius, 20.f);
}

TEST(GameObject, DefaultCircleUsesTheShorterSideAndTheScale)
{
    hitbox::GameObject object;
    object.setSize({60.f, 20.f});
    object.setPosition({0.f, 0.f});
    EXPECT_FLOAT_EQ(object.getBoundingCircle().radius, 10.f);
    EXPECT_EQ(object.getBoundingCircle().center, hitbox::Vec2(30.f, 10.f));
    object.setScale({2.f, 2.f});
    EXPECT_FLOAT_EQ(object.getBoundingCircle().radius, 20.f);
    // Stretched one way: still the circle inside the world box, whichever side is shorter.
    object.setScale({0.1f, 1.f}); // a 6 x 20 box
    EXPECT_FLOAT_EQ(object.getBoundingCircle().radius, 3.f);
    object.setScale({1.f, 3.f}); // a 60 x 60 box
    EXPECT_FLOAT_EQ(object.getBoundingCircle().radius, 30.f);
    EXPECT_EQ(object.getCollisionBox(), sf::FloatRect({0.f, 0.f}, {60.f, 60.f}));
}

TEST(GameObject, ConfiguredCircleIsMeasuredFromTheOriginPoint)
{
    hitbox::GameObject object;
    object.setSize({50.f, 50.f});
    object.setOrigin({25.f, 25.f});
    object.setPosition({100.f, 100.f});
    object.setBoundingCircle({0.f, -10.f}, 8.f);
    EXPECT_EQ(object.getBoundingCircle().center, hitbox::Vec2(100.f, 90.f));
    EXPECT_FLOAT_EQ(object.getBoundingCircle().radius, 8.f);
    object.clearBoundingCircle();
    EXPECT_FLOAT_EQ(object.getBoundingCircle().radius, 25.f);
}

TEST(GameObject, CircleTurnsWithTheObject)
{
    hitbox::GameObject object;
    object.setSize({50.f, 50.f});
    object.setOrigin({25.f, 25.f});
    object.setPosition({100.f, 100.f});
    object.setBoundingCircle({10.f, 0.f}, 5.f);
    hitbox::setRotationDegrees(object, 90.f);
    const hitbox::Circle circle = object.getBoundingCircle();
    EXPECT_NEAR(circle.center.x, 100.f, 1e-4f);
    EXPECT_NEAR(circle.center.y, 110.f, 1e-4f);
}
