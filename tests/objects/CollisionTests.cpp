// Collision: the static facade the lecture uses, on GameObjects.
#include "support/SfmlPrinters.h"

#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"

#include <gtest/gtest.h>

namespace
{

hitbox::GameObject makeSquare(float x, float y, float size)
{
    hitbox::GameObject square;
    square.setSize({size, size});
    square.setPosition({x, y});
    return square;
}

} // namespace

TEST(Collision, LectureBouncingBallsCallWorks)
{
    hitbox::GameObject ball1 = makeSquare(0.f, 0.f, 50.f);
    hitbox::GameObject ball2 = makeSquare(40.f, 0.f, 50.f);
    EXPECT_TRUE(hitbox::Collision::checkBoundingCircle(&ball1, &ball2));
    ball2.setPosition({50.f, 0.f}); // circles exactly touching
    EXPECT_FALSE(hitbox::Collision::checkBoundingCircle(&ball1, &ball2));
    ball1.collisionResponse(NULL); // the lecture's call: the default response does nothing
}

TEST(Collision, CircleComesFromTheCentreNotTheCorner)
{
    // With a centred origin, the lecture's formula put the circle a radius away from the
    // ball. Two balls whose drawn circles overlap must collide.
    hitbox::GameObject ball1 = makeSquare(100.f, 100.f, 40.f);
    hitbox::GameObject ball2 = makeSquare(135.f, 100.f, 40.f);
    ball1.setOrigin({20.f, 20.f});
    ball2.setOrigin({20.f, 20.f});
    EXPECT_TRUE(hitbox::Collision::checkBoundingCircle(&ball1, &ball2));
    ball2.setPosition({141.f, 100.f});
    EXPECT_FALSE(hitbox::Collision::checkBoundingCircle(&ball1, &ball2));
}

TEST(Collision, BoundingBoxTouchingIsNotACollision)
{
    hitbox::GameObject square1 = makeSquare(0.f, 200.f, 50.f);
    hitbox::GameObject square2 = makeSquare(50.f, 200.f, 50.f);
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(&square1, &square2));
    square2.move({-0.5f, 0.f});
    EXPECT_TRUE(hitbox::Collision::checkBoundingBox(&square1, &square2));
}

TEST(Collision, PointInBoxWithIntAndFloatPoints)
{
    hitbox::GameObject square = makeSquare(100.f, 100.f, 50.f);
    EXPECT_TRUE(hitbox::Collision::checkBoundingBox(&square, sf::Vector2i(120, 120)));
    EXPECT_TRUE(hitbox::Collision::checkBoundingBox(&square, sf::Vector2f(100.5f, 149.5f)));
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(&square, sf::Vector2i(150, 120)));
}

TEST(Collision, NullDeadNonColliderAndSelfNeverCollide)
{
    hitbox::GameObject a = makeSquare(0.f, 0.f, 50.f);
    hitbox::GameObject b = makeSquare(10.f, 10.f, 50.f);
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(nullptr, &b));
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(&a, nullptr));
    EXPECT_FALSE(hitbox::Collision::checkBoundingCircle(nullptr, nullptr));
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(static_cast<hitbox::GameObject*>(nullptr),
                                                     sf::Vector2i(1, 1)));
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(&a, &a));
    EXPECT_FALSE(hitbox::Collision::getBoundingBoxContact(nullptr, &b).hit);

    b.setCollider(false);
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(&a, &b));
    EXPECT_FALSE(hitbox::Collision::checkCircleBox(&a, &b));
    b.setCollider(true);
    b.setAlive(false);
    EXPECT_FALSE(hitbox::Collision::checkBoundingCircle(&a, &b));
    EXPECT_FALSE(hitbox::Collision::checkBoundingBox(&b, sf::Vector2f(20.f, 20.f)));
    b.setAlive(true);
    EXPECT_TRUE(hitbox::Collision::checkBoundingBox(&a, &b));
}

TEST(Collision, ContactVersionsAgreeWithTheYesNoTests)
{
    hitbox::GameObject a = makeSquare(0.f, 0.f, 50.f);
    hitbox::GameObject b = makeSquare(45.f, 10.f, 50.f);
    const hitbox::Contact boxes = hitbox::Collision::getBoundingBoxContact(&a, &b);
    ASSERT_TRUE(boxes.hit);
    EXPECT_EQ(boxes.normal, hitbox::Vec2(-1.f, 0.f)); // push a left, out of b
    EXPECT_FLOAT_EQ(boxes.depth, 5.f);

    const hitbox::Contact circles = hitbox::Collision::getBoundingCircleContact(&a, &b);
    EXPECT_EQ(circles.hit, hitbox::Collision::checkBoundingCircle(&a, &b));
    const hitbox::Contact circleBox = hitbox::Collision::getCircleBoxContact(&a, &b);
    EXPECT_EQ(circleBox.hit, hitbox::Collision::checkCircleBox(&a, &b));
}
