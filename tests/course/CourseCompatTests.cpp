// Course compatibility: code written for the course's old framework, through the old
// include paths (framework/compat/Framework/), builds and behaves as the README says.
// A course lab includes "Framework/GameObject.h"; these tests reach the same headers as
// "compat/Framework/..." because framework/ is already on the include path.
#include "support/SfmlPrinters.h"

#include "compat/Framework/Animation.h"
#include "compat/Framework/BaseLevel.h"
#include "compat/Framework/Collision.h"
#include "compat/Framework/GameObject.h"
#include "compat/Framework/Input.h"
#include "compat/Framework/Vector.h"
#include "compat/Framework/VectorHelper.h"

#include <gtest/gtest.h>

namespace
{

// A paddle as students write it: origin at the centre, box measured from the origin,
// keys read through the protected `input`, `velocity` and `window` members.
class Paddle : public GameObject
{
public:
    Paddle()
    {
        setSize(sf::Vector2f(20, 100));
        setOrigin({10, 50});
        setCollisionBox(-10, -50, 20, 100);
    }
    void handleInput(float) override
    {
        velocity.y = 0;
        if (input->isKeyDown(sf::Keyboard::Key::W))
            velocity.y = -speed;
    }
    void update(float dt) override { move(velocity * dt); }
    void collisionResponse(GameObject* other) override { lastHit = other; }

    GameObject* lastHit = this; // "this" until a response happens
    bool hasWindow() const { return window != nullptr; }

private:
    float speed = 400.f;
};

// A week-9 style level: derives from BaseLevel and sets the protected members itself.
class Level : public BaseLevel
{
public:
    Level(sf::RenderWindow* hwnd, Input* in)
    {
        window = hwnd;
        input = in;
        paddle.setInput(input);
        paddle.setWindow(window);
        paddle.setPosition({100, 300});
    }
    void handleInput(float dt) override { paddle.handleInput(dt); }
    void update(float dt) override { paddle.update(dt); }
    void render() override
    {
        beginDraw(); // a null window: nothing to draw on, and no crash
        endDraw();
    }
    Paddle paddle;
};

} // namespace

TEST(CourseCompat, StudentPaddleBoxCoversTheShapeAroundItsPosition)
{
    Paddle paddle;
    paddle.setPosition({100, 300});
    EXPECT_EQ(paddle.getCollisionBox(), sf::FloatRect({90, 250}, {20, 100}));
}

TEST(CourseCompat, LevelDrivesObjectsThroughTheProtectedInputPointer)
{
    Input input;
    Level level(nullptr, &input);
    input.setKeyDown(sf::Keyboard::Key::W);
    level.handleInput(0.5f);
    level.update(0.5f);
    level.render();
    EXPECT_EQ(level.paddle.getPosition(), sf::Vector2f(100, 100));
    EXPECT_FALSE(level.paddle.hasWindow());
}

TEST(CourseCompat, MainCppMouseEventsWithQualifiedMouseState)
{
    // The course's Main.cpp writes the enum name out: Input::MouseState::PRESSED.
    Input input;
    input.setMousePosition(40, 30);
    input.setLeftMouse(Input::MouseState::PRESSED);
    EXPECT_TRUE(input.isLeftMousePressed());
    input.update();
    EXPECT_TRUE(input.isLeftMouseDown());
    EXPECT_FALSE(input.isLeftMousePressed());
    input.setLeftMouse(Input::MouseState::UP);
    EXPECT_FALSE(input.isLeftMouseDown());
    EXPECT_TRUE(input.isLeftMouseReleased());
    input.update();
    EXPECT_FALSE(input.isLeftMouseReleased());

    input.setRightMouse(Input::MouseState::PRESSED);
    input.update();
    input.setRightMouse(Input::MouseState::UP);
    EXPECT_TRUE(input.isRightMouseReleased());
}

TEST(CourseCompat, ClickOnAnObjectWithTheIntMousePosition)
{
    Input input;
    Paddle paddle;
    paddle.setPosition({100, 300});
    input.setMousePosition(95, 260);
    EXPECT_TRUE(
        Collision::checkBoundingBox(&paddle, sf::Vector2i(input.getMouseX(), input.getMouseY())));
    input.setMousePosition(89, 260);
    EXPECT_FALSE(
        Collision::checkBoundingBox(&paddle, sf::Vector2i(input.getMouseX(), input.getMouseY())));
}

TEST(CourseCompat, LectureBallsWithTopLeftOriginCollideAsTheSlidesSay)
{
    // The lecture's balls: 100 x 100, origin at the top-left corner, no box set. The old
    // circle (top-left + size.x / 2) and Hitbox's (inscribed in the box) agree here.
    GameObject ball1;
    GameObject ball2;
    ball1.setSize(sf::Vector2f(100, 100));
    ball2.setSize(sf::Vector2f(100, 100));
    ball1.setPosition({0, 200});
    ball2.setPosition({99, 200}); // centres 99 apart, radii add to 100
    EXPECT_TRUE(Collision::checkBoundingCircle(&ball1, &ball2));
    ball2.setPosition({100, 200}); // exactly touching: not a collision
    EXPECT_FALSE(Collision::checkBoundingCircle(&ball1, &ball2));
}

TEST(CourseCompat, CollisionResponseWithNullMeansTheWorld)
{
    Paddle paddle;
    paddle.collisionResponse(NULL); // the lecture's spelling
    EXPECT_EQ(paddle.lastHit, nullptr);
}

TEST(CourseCompat, HelpersAndAnimationUnderTheOldNames)
{
    EXPECT_EQ(Vector::normalise(sf::Vector2f(0, 5)), sf::Vector2f(0, 1));
    EXPECT_FLOAT_EQ(VectorHelper::magnitude(sf::Vector2f(5, 12)), 13.f);
    Animation walk;
    walk.addFrame(sf::IntRect({0, 0}, {15, 21}));
    walk.setFrameSpeed(1.f / 10.f);
    walk.animate(0.05f);
    EXPECT_EQ(walk.getCurrentFrame(), sf::IntRect({0, 0}, {15, 21}));
}
