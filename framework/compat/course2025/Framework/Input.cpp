#include "Framework/Input.h"

bool Input::inRange(sf::Keyboard::Scancode key)
{
    const int code = static_cast<int>(key);
    return code >= 0 && code < static_cast<int>(sf::Keyboard::ScancodeCount);
}

void Input::setKeyDown(sf::Keyboard::Scancode key)
{
    if (!inRange(key))
        return;
    const auto code = static_cast<std::size_t>(key);
    if (!keysDown[code])
        keysPressed[code] = true; // a repeated "down" of a held key is no new press
    keysDown[code] = true;
}

void Input::setKeyUp(sf::Keyboard::Scancode key)
{
    if (inRange(key))
        keysDown[static_cast<std::size_t>(key)] = false;
}

bool Input::isKeyDown(sf::Keyboard::Scancode key) const
{
    return inRange(key) && keysDown[static_cast<std::size_t>(key)];
}

bool Input::isPressed(sf::Keyboard::Scancode key) const
{
    return inRange(key) && keysPressed[static_cast<std::size_t>(key)];
}

void Input::setMouseX(int x)
{
    mouseX = x;
}

void Input::setMouseY(int y)
{
    mouseY = y;
}

void Input::setMousePosition(int x, int y)
{
    mouseX = x;
    mouseY = y;
}

int Input::getMouseX() const
{
    return mouseX;
}

int Input::getMouseY() const
{
    return mouseY;
}

void Input::setButton(MouseState& button, MouseState state)
{
    // Main.cpp reports a button going down as DOWN; the first frame of it is PRESSED.
    if (state == MouseState::DOWN && button == MouseState::UP)
        state = MouseState::PRESSED;
    button = state;
}

void Input::setLeftMouse(MouseState state)
{
    setButton(leftButton, state);
}

bool Input::isLeftMouseDown() const
{
    return leftButton != MouseState::UP;
}

bool Input::isLeftMousePressed() const
{
    return leftButton == MouseState::PRESSED;
}

void Input::setRightMouse(MouseState state)
{
    setButton(rightButton, state);
}

bool Input::isRightMouseDown() const
{
    return rightButton != MouseState::UP;
}

bool Input::isRightMousePressed() const
{
    return rightButton == MouseState::PRESSED;
}

void Input::update()
{
    keysPressed.fill(false);
    if (leftButton == MouseState::PRESSED)
        leftButton = MouseState::DOWN;
    if (rightButton == MouseState::PRESSED)
        rightButton = MouseState::DOWN;
}
