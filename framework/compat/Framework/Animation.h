// Framework/Animation.h - the course's old include path for Animation (hitbox/Animation.h).
#pragma once

#include "hitbox/Animation.h"

#include <SFML/Graphics.hpp>
#include <vector>
