// Framework/Input.h - the course's old include path for Input (hitbox/Input.h).
#pragma once

#include "hitbox/Input.h"
