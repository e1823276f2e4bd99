#include "Framework/Input.h"

namespace
{

// One button's MouseState as Hitbox's down/up, and whether a press this frame is handled.
void setButton(Input& input, bool right, Input::MouseState state, bool& handled)
{
    if (right)
        input.setMouseRDown(state != Input::UP);
    else
        input.setMouseLDown(state != Input::UP);
    if (state != Input::UP) // a release keeps the press handled (or not) as it was
        handled = state == Input::DOWN;
}

} // namespace

void Input::setLeftMouse(MouseState state)
{
    setButton(*this, false, state, leftHandled);
}

void Input::setRightMouse(MouseState state)
{
    setButton(*this, true, state, rightHandled);
}

bool Input::isLeftMousePressed() const
{
    return hitbox::Input::isLeftMousePressed() && !leftHandled;
}

bool Input::isRightMousePressed() const
{
    return hitbox::Input::isRightMousePressed() && !rightHandled;
}

bool Input::isMouseLDown() const
{
    return isLeftMouseDown();
}

bool Input::isMouseRDown() const
{
    return isRightMouseDown();
}

void Input::update()
{
    hitbox::Input::update();
    leftHandled = false;
    rightHandled = false;
}
