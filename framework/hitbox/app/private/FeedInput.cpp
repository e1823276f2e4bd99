#include "hitbox/app/private/FeedInput.h"

namespace hitbox
{

void feedInput(Input& input, const WindowEvent& event)
{
    using Kind = WindowEvent::Kind;
    const bool pressed = event.kind == Kind::MouseButtonPressed;
    switch (event.kind)
    {
    case Kind::KeyPressed:
        input.setKeyDown(static_cast<int>(event.key));
        break;
    case Kind::KeyReleased:
        input.setKeyUp(static_cast<int>(event.key));
        break;
    case Kind::MouseButtonPressed:
    case Kind::MouseButtonReleased:
        if (event.button == sf::Mouse::Button::Left)
            input.setMouseLDown(pressed);
        else if (event.button == sf::Mouse::Button::Right)
            input.setMouseRDown(pressed);
        break;
    case Kind::MouseWheelScrolled:
        input.addMouseWheel(event.wheelDelta);
        break;
    case Kind::FocusLost:
        input.releaseAll();
        break;
    default:
        break;
    }
}

} // namespace hitbox
