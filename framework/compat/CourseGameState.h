// CourseGameState.h - the course's GameState, both generations (Framework/GameState.h and
// course2025/Framework/GameState.h include it): which screen a lab is on.
//
// The two frameworks differ only in the stored state's name: `currentState` in 2019-24,
// `m_currentState` in 2025-26 (course2025's header defines HITBOX_COURSE_2025 first). A
// lab's own GameState.cpp assigns it by that name, and so does each generation's
// Framework/GameState.cpp, which is also compiled against a lab's own GameState.h.
#pragma once

// The screens. A lab that added its own (e.g. GAME_OVER) did so in its own GameState.h, as
// the course's header says; that copy replaces the whole header (HitboxCourseLabFramework.cmake),
// so this enum is never edited here.
enum class State
{
    MENU,
    LEVEL,
    PAUSE,
    CREDITS
};

class GameState
{
public:
    void setCurrentState(State s);
    State getCurrentState();

protected:
    // A new GameState starts on the first state of the enum (the course's left it
    // uninitialised; Main.cpp always set it before reading it).
#ifdef HITBOX_COURSE_2025
    State m_currentState = State();
#else
    State currentState = State();
#endif
};
