// Framework/Collision.h - the course's old include path for Collision (hitbox/objects/Collision.h).
#pragma once

#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics.hpp>
