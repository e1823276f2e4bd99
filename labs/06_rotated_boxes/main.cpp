// Lab 6 - Rotated boxes
// Teaches: the separating axis theorem. Rotated boxes are tested by projecting both onto
// each edge normal: a gap on any axis means apart (a line fits between them); overlap on all
// of them gives the minimum translation vector, the shortest way out. One capsule joins in.
// Keys: drag a shape with the mouse, wheel turns it, Space pushes it out along the MTV,
// Tab holds the next shape, plus the shared keys (F1: outlines).
#include "RotatedLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 6 - Rotated boxes"},
                       [](const hitbox::Options&) { return std::make_unique<RotatedLevel>(); });
}
