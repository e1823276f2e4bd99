// BroadphasePrinters.h - how Google Test prints the broadphase tests' parameters, so a test
// list or a failure says "Grid" instead of "4-byte object <02-00 00-00>".
#pragma once

#include "Scenes.h"

#include "hitbox/broadphase/Broadphase.h"

#include <ostream>

namespace hitbox
{
// Found by Google Test through the enum's namespace (argument-dependent lookup).
inline void PrintTo(BroadphaseMethod method, std::ostream* out)
{
    *out << toString(method);
}
} // namespace hitbox

namespace scenes
{
inline void PrintTo(Kind kind, std::ostream* out)
{
    *out << describe(kind);
}
} // namespace scenes
