// Framework/BaseLevel.h - the course's old include path for BaseLevel
// (hitbox/course/BaseLevel.h). SFML's graphics and Input come along, as they did in the old header.
#pragma once

#include "hitbox/app/Input.h"
#include "hitbox/course/BaseLevel.h"

#include <SFML/Graphics.hpp>
#include <string>
