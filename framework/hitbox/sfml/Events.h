// Events.h - what happened in a window, in one form for SFML 2 and SFML 3.
//
// SFML 3 returns events as std::optional<sf::Event> holding one of several types; SFML 2
// fills in a union with a `type` field. The app layer reads this struct instead of either.
#pragma once

#include <SFML/System/Vector2.hpp>
#include <SFML/Window/Keyboard.hpp>
#include <SFML/Window/Mouse.hpp>

namespace sf
{
class Window;
}

namespace hitbox
{

struct WindowEvent
{
    enum class Kind
    {
        Closed,
        KeyPressed,
        KeyReleased,
        MouseButtonPressed,
        MouseButtonReleased,
        MouseMoved,
        MouseWheelScrolled,
        FocusLost,
        FocusGained,
        Other // anything the framework does not use (resizes are read from the window)
    };
    Kind kind = Kind::Other;
    sf::Keyboard::Key key = sf::Keyboard::Key::Unknown; // KeyPressed, KeyReleased
    sf::Mouse::Button button = sf::Mouse::Button::Left; // MouseButtonPressed, ...Released
    sf::Vector2i mousePixel;                            // MouseMoved
    float wheelDelta = 0.f;                             // MouseWheelScrolled: notches, up > 0
};

// Takes the next waiting event of `window` into `event`; false when none is waiting.
[[nodiscard]] bool pollEvent(sf::Window& window, WindowEvent& event);

} // namespace hitbox
