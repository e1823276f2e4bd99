// Framework/BaseLevel.h - the course's old include path for BaseLevel
// (hitbox/BaseLevel.h). SFML's graphics and Input come along, as they did in the old header.
#pragma once

#include "hitbox/BaseLevel.h"
#include "hitbox/Input.h"

#include <SFML/Graphics.hpp>
#include <string>
