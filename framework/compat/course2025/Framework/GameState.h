// Framework/GameState.h (2025-26 course framework) - which screen a lab is on.
//
// The course invites students to add states to the enum below, so a lab's own GameState.h
// (in Framework/ or beside Main.cpp) is the one its code and BaseLevel see, not this file
// (HitboxCourseLab.cmake puts the lab's copy first on the include path).
#pragma once

#include "../../CourseState.h" // enum class State: MENU, LEVEL, PAUSE, CREDITS

class GameState
{
public:
    void setCurrentState(State s);
    State getCurrentState();

protected:
    // A new GameState starts on the first state of the enum.
    State m_currentState = State();
};
