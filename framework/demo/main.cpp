// Sandbox - the Hitbox framework demo.
// Teaches: what the collision tests answer, seen live. Move a box (or a circle) over boxes
// and circles; press F1 to see collision outlines turn hatched (colliding) or dashed (only
// touching) and the contact normals.
// Keys: mouse moves the shape, click or Space switches box/circle, plus the shared keys.
#include "SandboxLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Hitbox sandbox"},
                       [](const hitbox::Options&) { return std::make_unique<SandboxLevel>(); });
}
