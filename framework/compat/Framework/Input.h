// Framework/Input.h - the course's Input: Hitbox's (hitbox/app/Input.h) under the course's name,
// with the two ways the course's weeks set and read the mouse buttons:
//     input->setMouseLDown(true);  input->isMouseLDown()                     (early weeks)
//     input->setLeftMouse(Input::MouseState::PRESSED);  isLeftMousePressed()  (later weeks)
// Both feed the same buttons, so the questions of either style see what the other set.
#pragma once

#include "hitbox/app/Input.h"

class Input : public hitbox::Input
{
public:
    enum MouseState
    {
        UP,
        DOWN,
        PRESSED // went down this frame
    };

    // The later weeks' setter. PRESSED: the button went down (a press until update()). UP: it
    // went up (a release). DOWN: it is held and any press this frame is handled: old code sets
    // DOWN after acting on a click so that it acts once, so isLeftMousePressed() is false.
    void setLeftMouse(MouseState state);
    void setRightMouse(MouseState state);
    // Hitbox's questions, less a press that DOWN marked handled.
    [[nodiscard]] bool isLeftMousePressed() const;
    [[nodiscard]] bool isRightMousePressed() const;
    // The early weeks' question: is the button held?
    [[nodiscard]] bool isMouseLDown() const;
    [[nodiscard]] bool isMouseRDown() const;

    // End of frame (Hitbox's update()): handled presses are forgotten with the rest.
    void update();

private:
    bool leftHandled = false; // DOWN was set since the last update()
    bool rightHandled = false;
};
