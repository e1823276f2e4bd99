// Input: down / pressed this frame / released this frame, the mouse, and bad key codes.
#include "support/SfmlPrinters.h"

#include "hitbox/app/Input.h"

#include <gtest/gtest.h>

TEST(Input, PressIsSeenForOneFrameDownUntilReleased)
{
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::W);
    EXPECT_TRUE(input.isKeyDown(sf::Keyboard::Key::W));
    EXPECT_TRUE(input.isPressed(sf::Keyboard::Key::W));
    input.update();
    EXPECT_TRUE(input.isKeyDown(sf::Keyboard::Key::W));
    EXPECT_FALSE(input.isPressed(sf::Keyboard::Key::W));
    input.setKeyUp(sf::Keyboard::Key::W);
    EXPECT_FALSE(input.isKeyDown(sf::Keyboard::Key::W));
    EXPECT_TRUE(input.isReleased(sf::Keyboard::Key::W));
    input.update();
    EXPECT_FALSE(input.isReleased(sf::Keyboard::Key::W));
}

TEST(Input, KeyRepeatIsNotANewPress)
{
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Space);
    input.update();
    input.setKeyDown(sf::Keyboard::Key::Space); // the operating system's auto-repeat
    EXPECT_FALSE(input.isPressed(sf::Keyboard::Key::Space));
}

TEST(Input, PressAndReleaseInOneFrameIsStillAPress)
{
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::A);
    input.setKeyUp(sf::Keyboard::Key::A);
    EXPECT_TRUE(input.isPressed(sf::Keyboard::Key::A));
    EXPECT_TRUE(input.isReleased(sf::Keyboard::Key::A));
    EXPECT_FALSE(input.isKeyDown(sf::Keyboard::Key::A));
}

TEST(Input, UnknownAndOutOfRangeKeysAreIgnored)
{
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Unknown); // -1: the old framework wrote outside its array
    input.setKeyDown(100000);
    EXPECT_FALSE(input.isKeyDown(sf::Keyboard::Key::Unknown));
    EXPECT_FALSE(input.isKeyDown(100000));
    EXPECT_FALSE(input.isPressed(-5));
}

TEST(Input, MousePositionFloatAndInt)
{
    hitbox::Input input;
    input.setMousePosition(sf::Vector2f(10.6f, 20.2f));
    EXPECT_EQ(input.getMousePosition(), sf::Vector2f(10.6f, 20.2f));
    EXPECT_EQ(input.getMouseX(), 11);
    EXPECT_EQ(input.getMouseY(), 20);
    input.setMouseX(5);
    input.setMouseY(6);
    EXPECT_EQ(input.getMousePosition(), sf::Vector2f(5.f, 6.f));
    input.setMousePosition(7, 8);
    EXPECT_EQ(input.getMouseX(), 7);
}

TEST(Input, MouseButtonsDownPressedReleased)
{
    hitbox::Input input;
    input.setMouseLDown(true);
    EXPECT_TRUE(input.isLeftMouseDown());
    EXPECT_TRUE(input.isLeftMousePressed());
    input.setMouseLDown(true); // a repeated "down" is no new press
    input.update();
    EXPECT_TRUE(input.isLeftMouseDown());
    EXPECT_FALSE(input.isLeftMousePressed());
    input.setMouseLDown(false);
    EXPECT_TRUE(input.isLeftMouseReleased());
    EXPECT_FALSE(input.isLeftMouseDown());

    input.setMouseRDown(true);
    EXPECT_TRUE(input.isRightMousePressed());
    EXPECT_FALSE(input.isLeftMousePressed()); // the buttons are separate
    input.update();
    EXPECT_TRUE(input.isRightMouseDown());
    EXPECT_FALSE(input.isRightMousePressed());
}

TEST(Input, AClickShorterThanAFrameIsStillAPressAndARelease)
{
    // A touchpad tap: the button goes down and up again before the level reads the input.
    hitbox::Input input;
    input.setMouseLDown(true);
    input.setMouseLDown(false);
    EXPECT_TRUE(input.isLeftMousePressed());
    EXPECT_TRUE(input.isLeftMouseReleased());
    EXPECT_FALSE(input.isLeftMouseDown());
    input.update();
    EXPECT_FALSE(input.isLeftMousePressed());
    EXPECT_FALSE(input.isLeftMouseReleased());
}

TEST(Input, ReleaseAllLetsGoOfHeldKeys)
{
    // Focus lost while a key is held: its "up" event never comes.
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Up);
    input.setMouseLDown(true);
    input.releaseAll();
    EXPECT_FALSE(input.isKeyDown(sf::Keyboard::Key::Up));
    EXPECT_FALSE(input.isLeftMouseDown());
}

TEST(Input, WheelIsPerFrame)
{
    hitbox::Input input;
    input.addMouseWheel(1.f);
    input.addMouseWheel(2.f);
    EXPECT_FLOAT_EQ(input.getMouseWheel(), 3.f);
    input.update();
    EXPECT_FLOAT_EQ(input.getMouseWheel(), 0.f);
}
