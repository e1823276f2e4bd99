// Poses as an objects/ file (tests/CMakeLists.txt) that names the app layer's Input without
// including it, as GameObject.h once did for the course's pointers: refused, no exceptions.
#pragma once

namespace hitbox
{
class Input;
}
