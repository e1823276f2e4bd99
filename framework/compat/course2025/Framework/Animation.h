// Framework/Animation.h (2025-26 course framework) - the course's include path for Hitbox's
// Animation (hitbox/objects/Animation.h): the same class, stop() and pause() included, on
// SFML 3's rectangles.
#pragma once

#include "hitbox/objects/Animation.h"

// The course's code names the class without Hitbox's namespace.
using Animation = hitbox::Animation;
