// Framework/VectorHelper.h - the later weeks' name for the Vector helpers (normalise, magnitude,
// dot).
//
// The course renamed Vector to VectorHelper part way through; old lab code uses either
// name, so this is the same class under the second name.
#pragma once

#include "Framework/Vector.h"

#include <SFML/Graphics.hpp>
#include <cmath>

using VectorHelper = Vector;
