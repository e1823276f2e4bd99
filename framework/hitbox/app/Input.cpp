#include "hitbox/app/Input.h"

#include "hitbox/app/Keys.h"

#include <cmath>

namespace
{

bool isKnownKey(int key)
{
    return key >= 0 && key < hitbox::keyCount;
}

} // namespace

namespace hitbox
{

void Input::setKeyDown(int key)
{
    if (!isKnownKey(key))
        return;
    // Held keys repeat their "down" event; only the first one is a press.
    if (!keysDown[key])
        keysPressed[key] = true;
    keysDown[key] = true;
}

void Input::setKeyUp(int key)
{
    if (!isKnownKey(key))
        return;
    if (keysDown[key])
        keysReleased[key] = true;
    keysDown[key] = false;
}

bool Input::isKeyDown(int key) const
{
    return isKnownKey(key) && keysDown[key];
}

bool Input::isPressed(int key) const
{
    return isKnownKey(key) && keysPressed[key];
}

bool Input::isReleased(int key) const
{
    return isKnownKey(key) && keysReleased[key];
}

void Input::setMouseX(int x)
{
    mousePosition.x = static_cast<float>(x);
}

void Input::setMouseY(int y)
{
    mousePosition.y = static_cast<float>(y);
}

void Input::setMousePosition(int x, int y)
{
    mousePosition = {static_cast<float>(x), static_cast<float>(y)};
}

void Input::setMousePosition(sf::Vector2f position)
{
    mousePosition = position;
}

int Input::getMouseX() const
{
    return static_cast<int>(std::lround(mousePosition.x));
}

int Input::getMouseY() const
{
    return static_cast<int>(std::lround(mousePosition.y));
}

sf::Vector2f Input::getMousePosition() const
{
    return mousePosition;
}

void Input::press(Button& button, bool down)
{
    // Held buttons may repeat their "down": only the first one is a press.
    if (down && !button.down)
        button.pressed = true;
    if (!down && button.down)
        button.released = true;
    button.down = down;
}

void Input::setMouseLDown(bool down)
{
    press(leftButton, down);
}

void Input::setMouseRDown(bool down)
{
    press(rightButton, down);
}

bool Input::isLeftMouseDown() const
{
    return leftButton.down;
}

bool Input::isLeftMousePressed() const
{
    return leftButton.pressed;
}

bool Input::isLeftMouseReleased() const
{
    return leftButton.released;
}

bool Input::isRightMouseDown() const
{
    return rightButton.down;
}

bool Input::isRightMousePressed() const
{
    return rightButton.pressed;
}

bool Input::isRightMouseReleased() const
{
    return rightButton.released;
}

void Input::addMouseWheel(float delta)
{
    mouseWheel += delta;
}

float Input::getMouseWheel() const
{
    return mouseWheel;
}

void Input::releaseAll()
{
    for (int key = 0; key < hitbox::keyCount; ++key)
        setKeyUp(key);
    setMouseLDown(false);
    setMouseRDown(false);
}

void Input::update()
{
    keysPressed.fill(false);
    keysReleased.fill(false);
    for (Button* button : {&leftButton, &rightButton})
    {
        button->pressed = false;
        button->released = false;
    }
    mouseWheel = 0.f;
}

} // namespace hitbox
