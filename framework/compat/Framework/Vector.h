// Framework/Vector.h - the course's old include path for the Vector helpers
// (hitbox/course/Vector.h).
#pragma once

#include "hitbox/course/Vector.h"

#include <SFML/Graphics.hpp>
#include <cmath>
