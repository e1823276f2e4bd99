// Framework/GameState.h - which screen a course lab is on (menu, level, pause, credits).
//
// The course's header invites students to add their own states to the enum below, and most
// labs did: so when a lab folder has its own Framework/GameState.h, that copy is the one its
// code sees (and its own Framework/GameState.cpp, if it has one), not this file.
#pragma once

#include "../CourseState.h" // enum class State: MENU, LEVEL, PAUSE, CREDITS

class GameState
{
public:
    void setCurrentState(State s);
    State getCurrentState();

protected:
    // A new GameState starts on the first state of the enum (the old framework left it
    // uninitialised; Main.cpp always set it before reading it).
    State currentState = State();
};
