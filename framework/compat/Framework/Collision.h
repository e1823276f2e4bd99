// Framework/Collision.h - the course's old include path for Collision (hitbox/Collision.h).
#pragma once

#include "hitbox/Collision.h"
#include "hitbox/GameObject.h"

#include <SFML/Graphics.hpp>
