// Framework/Animation.h - the course's old include path for Animation (hitbox/objects/Animation.h).
#pragma once

#include "hitbox/objects/Animation.h"

#include <SFML/Graphics.hpp>
#include <vector>

// The course's code names the class without Hitbox's namespace.
using Animation = hitbox::Animation;
