// CourseState.h - the screens a course lab can be on: the enum both generations' GameState.h
// use (Framework/GameState.h, course2025/Framework/GameState.h) when the lab has no
// GameState.h of its own. A lab that added states has its own copy, which replaces the whole
// GameState.h (HitboxCourseLabFramework.cmake), so this enum is never edited here.
#pragma once

// Add your own (e.g. GAME_OVER) in your lab's GameState.h, as the course's header says.
enum class State
{
    MENU,
    LEVEL,
    PAUSE,
    CREDITS
};
