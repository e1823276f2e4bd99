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
    // A click shorter than a frame (a touchpad tap) is both pressed and released this frame.
    if (down && button.state == UP)
    {
        button.state = PRESSED;
        button.pressed = true;
    }
    if (!down && button.state != UP)
    {
        button.state = UP;
        button.released = true;
    }
}

void Input::setState(Button& button, MouseState state)
{
    // Old lab code reports a release as setLeftMouse(UP): count it as one.
    if (state == UP && button.state != UP)
        button.released = true;
    if (state != UP) // PRESSED says it went down; DOWN says it is held (no press this frame)
        button.pressed = state == PRESSED;
    button.state = state;
}

void Input::setMouseLDown(bool down)
{
    press(leftButton, down);
}

bool Input::isMouseLDown() const
{
    return leftButton.state != UP;
}

void Input::setMouseRDown(bool down)
{
    press(rightButton, down);
}

bool Input::isMouseRDown() const
{
    return rightButton.state != UP;
}

void Input::setLeftMouse(MouseState state)
{
    setState(leftButton, state);
}

bool Input::isLeftMouseDown() const
{
    return leftButton.state != UP;
}

bool Input::isLeftMousePressed() const
{
    return leftButton.pressed;
}

bool Input::isLeftMouseReleased() const
{
    return leftButton.released;
}

void Input::setRightMouse(MouseState state)
{
    setState(rightButton, state);
}

bool Input::isRightMouseDown() const
{
    return rightButton.state != UP;
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
        if (button->state == PRESSED)
            button->state = DOWN;
        button->pressed = false;
        button->released = false;
    }
    mouseWheel = 0.f;
}
