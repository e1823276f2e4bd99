// Framework/Input.h - the course's old include path for Input (hitbox/app/Input.h).
#pragma once

#include "hitbox/app/Input.h"
