// Framework/VectorHelper.h - the course's old include path for VectorHelper
// (hitbox/course/VectorHelper.h).
#pragma once

#include "hitbox/course/VectorHelper.h"

#include <SFML/Graphics.hpp>
#include <cmath>
