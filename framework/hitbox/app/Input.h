// Input.h - what the keyboard and mouse are doing, as plain state a test can set.
//
// The window's events feed it (hitbox::App does that for you); a test sets keys and the
// mouse directly, so every rule can be tested without a window. One way to set each button
// (setMouseLDown) and one family of questions (isLeftMouseDown, ...Pressed, ...Released); the
// course's other names for them (setLeftMouse(MouseState), isMouseLDown) are its Input, in
// framework/compat/Framework/Input.h, built on this one.
//
// "This frame" means until update() is called: hitbox::App calls it after the first
// simulation step that saw the press, so a press is seen by exactly one step.
#pragma once

#include <SFML/System/Vector2.hpp>
#include <SFML/Window/Keyboard.hpp>

#include <array>

namespace hitbox
{

class Input
{
public:
    // Keys are sf::Keyboard::Key values (sf::Keyboard::Key::W) or their int codes. Codes
    // outside the keyboard's range, such as sf::Keyboard::Key::Unknown (-1), are ignored.
    void setKeyDown(int key);
    void setKeyUp(int key);
    [[nodiscard]] bool isKeyDown(int key) const;
    [[nodiscard]] bool isPressed(int key) const;  // went down this frame
    [[nodiscard]] bool isReleased(int key) const; // went up this frame
    // The same with sf::Keyboard::Key, which SFML 3 no longer converts to int by itself.
    void setKeyDown(sf::Keyboard::Key key) { setKeyDown(static_cast<int>(key)); }
    void setKeyUp(sf::Keyboard::Key key) { setKeyUp(static_cast<int>(key)); }
    [[nodiscard]] bool isKeyDown(sf::Keyboard::Key key) const
    {
        return isKeyDown(static_cast<int>(key));
    }
    [[nodiscard]] bool isPressed(sf::Keyboard::Key key) const
    {
        return isPressed(static_cast<int>(key));
    }
    [[nodiscard]] bool isReleased(sf::Keyboard::Key key) const
    {
        return isReleased(static_cast<int>(key));
    }

    // The mouse position. In Hitbox programs it is in world coordinates (already mapped
    // through the view, so it stays right after a resize); the int versions round it.
    void setMouseX(int x);
    void setMouseY(int y);
    void setMousePosition(int x, int y);
    void setMousePosition(sf::Vector2f position);
    [[nodiscard]] int getMouseX() const;
    [[nodiscard]] int getMouseY() const;
    [[nodiscard]] sf::Vector2f getMousePosition() const;

    // A button going down (true) or up (false). A press shorter than a frame (a touchpad
    // tap: down and up before update()) is both pressed and released this frame.
    void setMouseLDown(bool down);
    void setMouseRDown(bool down);
    [[nodiscard]] bool isLeftMouseDown() const;     // held now
    [[nodiscard]] bool isLeftMousePressed() const;  // went down this frame
    [[nodiscard]] bool isLeftMouseReleased() const; // went up this frame
    [[nodiscard]] bool isRightMouseDown() const;
    [[nodiscard]] bool isRightMousePressed() const;
    [[nodiscard]] bool isRightMouseReleased() const;

    // Wheel movement this frame: positive is away from the user.
    void addMouseWheel(float delta);
    [[nodiscard]] float getMouseWheel() const;

    // Let go of every key and button (the window lost focus: their "up" events will never
    // arrive, so without this a held key would stay down forever).
    void releaseAll();

    // End of frame: forget presses, releases and wheel movement; keep what is held down.
    void update();

private:
    struct Button
    {
        bool down = false;
        bool pressed = false;  // went down this frame (stays true if it also went up again)
        bool released = false; // went up this frame
    };
    static void press(Button& button, bool down);

    std::array<bool, sf::Keyboard::KeyCount> keysDown{};
    std::array<bool, sf::Keyboard::KeyCount> keysPressed{};
    std::array<bool, sf::Keyboard::KeyCount> keysReleased{};
    sf::Vector2f mousePosition;
    Button leftButton;
    Button rightButton;
    float mouseWheel = 0.f;
};

} // namespace hitbox
