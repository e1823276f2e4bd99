// Framework/VectorHelper.h - the course's old include path for VectorHelper
// (hitbox/VectorHelper.h).
#pragma once

#include "hitbox/VectorHelper.h"

#include <SFML/Graphics.hpp>
#include <cmath>
