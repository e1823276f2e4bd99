// Framework/GameObject.h - the course's old include path for GameObject.
//
// Old lab code writes #include "Framework/GameObject.h"; the class itself is Hitbox's
// (hitbox/objects/GameObject.h). SFML's graphics and Input come along, as they did in the old
// header, because lab code relies on them arriving with it.
#pragma once

#include "hitbox/app/Input.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics.hpp>
