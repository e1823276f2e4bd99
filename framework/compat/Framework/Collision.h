// Framework/Collision.h - the course's old include path for Collision (hitbox/objects/Collision.h).
#pragma once

#include "Framework/GameObject.h"
#include "hitbox/objects/Collision.h"

#include <SFML/Graphics.hpp>

// The course's code names the class without Hitbox's namespace.
using Collision = hitbox::Collision;
