// Framework/Input.h (2025-26 course framework) - the keyboard and mouse as plain state.
//
// The lab's Main.cpp feeds it from SFML 3's events (keys by sf::Keyboard::Scancode, the
// mouse in window pixels) and calls update() last in every frame. Behaviour as in Hitbox's
// Input for the older labs: a key held down (the window repeats its event) is pressed once;
// Scancodes outside the keyboard's range (sf::Keyboard::Scan::Unknown) are ignored.
#pragma once

#include <SFML/Window/Keyboard.hpp>
#include <array>

class Input
{
public:
    enum class MouseState
    {
        UP,
        DOWN,
        PRESSED // went down this frame
    };

    void setKeyDown(sf::Keyboard::Scancode key);
    void setKeyUp(sf::Keyboard::Scancode key);
    bool isKeyDown(sf::Keyboard::Scancode key) const;
    bool isPressed(sf::Keyboard::Scancode key) const; // went down this frame

    void setMouseX(int x);
    void setMouseY(int y);
    void setMousePosition(int x, int y);
    int getMouseX() const;
    int getMouseY() const;

    void setLeftMouse(MouseState state);
    bool isLeftMouseDown() const;    // DOWN or PRESSED
    bool isLeftMousePressed() const; // went down this frame
    void setRightMouse(MouseState state);
    bool isRightMouseDown() const;
    bool isRightMousePressed() const;

    // End of frame: forget what was pressed this frame; keep what is held down.
    void update();

private:
    static bool inRange(sf::Keyboard::Scancode key);
    static void setButton(MouseState& button, MouseState state);

    std::array<bool, sf::Keyboard::ScancodeCount> keysDown{};
    std::array<bool, sf::Keyboard::ScancodeCount> keysPressed{};
    int mouseX = 0;
    int mouseY = 0;
    MouseState leftButton = MouseState::UP;
    MouseState rightButton = MouseState::UP;
};
