// Framework/GameState.h (2025-26 course framework) - which screen a lab is on.
//
// The course invites students to add states to the enum, so a lab's own GameState.h (in
// Framework/ or beside Main.cpp) is the one its code and BaseLevel see, not this file
// (HitboxCourseLab.cmake puts the lab's copy first on the include path). The class, shared
// with the older framework, is in ../../CourseGameState.h; this generation names the stored
// state `m_currentState`.
#pragma once

#define HITBOX_COURSE_2025
#include "../../CourseGameState.h"
