#include "hitbox/sfml/Events.h"

#include <SFML/Window/Event.hpp>
#include <SFML/Window/Window.hpp>

namespace hitbox
{
namespace
{

void setKey(WindowEvent& event, WindowEvent::Kind kind, sf::Keyboard::Key key)
{
    event.kind = kind;
    event.key = key;
}

void setButton(WindowEvent& event, WindowEvent::Kind kind, sf::Mouse::Button button)
{
    event.kind = kind;
    event.button = button;
}

} // namespace

#if SFML_VERSION_MAJOR >= 3

bool pollEvent(sf::Window& window, WindowEvent& event)
{
    const std::optional<sf::Event> next = window.pollEvent();
    if (!next)
        return false;
    event = WindowEvent{};
    using Kind = WindowEvent::Kind;
    if (next->is<sf::Event::Closed>())
        event.kind = Kind::Closed;
    else if (const auto* pressedKey = next->getIf<sf::Event::KeyPressed>())
        setKey(event, Kind::KeyPressed, pressedKey->code);
    else if (const auto* releasedKey = next->getIf<sf::Event::KeyReleased>())
        setKey(event, Kind::KeyReleased, releasedKey->code);
    else if (const auto* pressedButton = next->getIf<sf::Event::MouseButtonPressed>())
        setButton(event, Kind::MouseButtonPressed, pressedButton->button);
    else if (const auto* releasedButton = next->getIf<sf::Event::MouseButtonReleased>())
        setButton(event, Kind::MouseButtonReleased, releasedButton->button);
    else if (const auto* move = next->getIf<sf::Event::MouseMoved>())
    {
        event.kind = Kind::MouseMoved;
        event.mousePixel = move->position;
    }
    else if (const auto* wheel = next->getIf<sf::Event::MouseWheelScrolled>())
    {
        if (wheel->wheel == sf::Mouse::Wheel::Vertical)
        {
            event.kind = Kind::MouseWheelScrolled;
            event.wheelDelta = wheel->delta;
        }
    }
    else if (next->is<sf::Event::FocusLost>())
        event.kind = Kind::FocusLost;
    else if (next->is<sf::Event::FocusGained>())
        event.kind = Kind::FocusGained;
    return true;
}

#else

bool pollEvent(sf::Window& window, WindowEvent& event)
{
    sf::Event next;
    if (!window.pollEvent(next))
        return false;
    event = WindowEvent{};
    using Kind = WindowEvent::Kind;
    switch (next.type)
    {
    case sf::Event::Closed:
        event.kind = Kind::Closed;
        break;
    case sf::Event::KeyPressed:
        setKey(event, Kind::KeyPressed, next.key.code);
        break;
    case sf::Event::KeyReleased:
        setKey(event, Kind::KeyReleased, next.key.code);
        break;
    case sf::Event::MouseButtonPressed:
        setButton(event, Kind::MouseButtonPressed, next.mouseButton.button);
        break;
    case sf::Event::MouseButtonReleased:
        setButton(event, Kind::MouseButtonReleased, next.mouseButton.button);
        break;
    case sf::Event::MouseMoved:
        event.kind = Kind::MouseMoved;
        event.mousePixel = {next.mouseMove.x, next.mouseMove.y};
        break;
    case sf::Event::MouseWheelScrolled:
        if (next.mouseWheelScroll.wheel == sf::Mouse::VerticalWheel)
        {
            event.kind = Kind::MouseWheelScrolled;
            event.wheelDelta = next.mouseWheelScroll.delta;
        }
        break;
    case sf::Event::LostFocus:
        event.kind = Kind::FocusLost;
        break;
    case sf::Event::GainedFocus:
        event.kind = Kind::FocusGained;
        break;
    default:
        break;
    }
    return true;
}

#endif

} // namespace hitbox
