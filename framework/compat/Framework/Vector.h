// Framework/Vector.h - the course's old include path for the Vector helpers
// (hitbox/Vector.h).
#pragma once

#include "hitbox/Vector.h"

#include <SFML/Graphics.hpp>
#include <cmath>
