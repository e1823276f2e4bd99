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
#include "hitbox/objects/World.h"

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

TEST(CourseCompat, OldStyleOverrideIsCalledByAWorldAndThroughHitboxsHook)
{
    // Old code overrides collisionResponse(GameObject*) with the course's GameObject; a World
    // (and any Hitbox code) calls Hitbox's hook, which must reach that override.
    Paddle left;
    Paddle right;
    left.setPosition({100, 300});
    right.setPosition({105, 300}); // overlapping boxes
    hitbox::World world;
    world.add(left);
    world.add(right);
    EXPECT_EQ(world.checkCollisions(), 1u);
    EXPECT_EQ(left.lastHit, &right);
    EXPECT_EQ(right.lastHit, &left);

    hitbox::GameObject& seenByHitbox = left;
    seenByHitbox.collisionResponse(nullptr); // the world (a wall), as Hitbox says it
    EXPECT_EQ(left.lastHit, nullptr);
}

TEST(CourseCompat, AnAssignedCollisionBoxIsTheOneCollisionsRead)
{
    // Old code assigns the member instead of calling setCollisionBox.
    class Crate : public GameObject
    {
    public:
        Crate()
        {
            setSize(sf::Vector2f(50, 50));
            collisionBox = sf::FloatRect({10, 10}, {30, 30});
        }
        sf::FloatRect assigned() const { return collisionBox; }
    };
    Crate crate;
    crate.setPosition({100, 100});
    EXPECT_EQ(crate.getCollisionBox(), sf::FloatRect({110, 110}, {30, 30}));
    EXPECT_EQ(crate.getBoundingCircle().radius, 15.f); // inscribed in the assigned box
    GameObject point;
    point.setSize({1, 1});
    point.setPosition({105, 105}); // inside the shape, outside the assigned box
    EXPECT_FALSE(Collision::checkBoundingBox(&crate, &point));
    crate.setCollisionBox(0, 0, 50, 50); // the setter and the member are one box
    EXPECT_EQ(crate.assigned(), sf::FloatRect({0, 0}, {50, 50}));
    EXPECT_TRUE(Collision::checkBoundingBox(&crate, &point));
    crate.clearCollisionBox();
    EXPECT_EQ(crate.assigned(), sf::FloatRect()); // {0, 0, 0, 0} until assigned, as in the course
    EXPECT_EQ(crate.getCollisionBox(), sf::FloatRect({100, 100}, {50, 50})); // the whole shape
}

TEST(CourseCompat, BothMouseStylesFeedTheSameButtons)
{
    Input input;
    input.setMouseLDown(true); // the early weeks' style
    EXPECT_TRUE(input.isMouseLDown());
    EXPECT_TRUE(input.isLeftMousePressed());
    input.update();
    input.setLeftMouse(Input::UP); // the later weeks' style
    EXPECT_FALSE(input.isMouseLDown());
    EXPECT_TRUE(input.isLeftMouseReleased());

    // PRESSED then UP in one frame: a press and a release.
    input.setRightMouse(Input::PRESSED);
    input.setRightMouse(Input::UP);
    EXPECT_TRUE(input.isRightMousePressed());
    EXPECT_TRUE(input.isRightMouseReleased());
    // Old code marks a press handled by setting DOWN: no press any more, still held, and a
    // release in the same frame does not bring the press back.
    input.update();
    input.setLeftMouse(Input::PRESSED);
    input.setLeftMouse(Input::DOWN);
    EXPECT_FALSE(input.isLeftMousePressed());
    EXPECT_TRUE(input.isLeftMouseDown());
    input.setLeftMouse(Input::UP);
    EXPECT_FALSE(input.isLeftMousePressed());
    input.update();
    input.setLeftMouse(Input::PRESSED); // a new frame's click is a press again
    EXPECT_TRUE(input.isLeftMousePressed());
}
