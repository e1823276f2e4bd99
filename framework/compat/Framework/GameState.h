// Framework/GameState.h - which screen a course lab is on (menu, level, pause, credits).
//
// The course's header invites students to add their own states to the enum, and most labs
// did: so when a lab folder has its own Framework/GameState.h, that copy is the one its code
// sees (and its own Framework/GameState.cpp, if it has one), not this file. The class, shared
// with the 2025-26 framework, is in ../CourseGameState.h (the stored state: `currentState`).
#pragma once

#include "../CourseGameState.h"
