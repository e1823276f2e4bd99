// Lab 6 - Rotated boxes
// Teaches: the separating axis theorem. Rotated boxes are tested by projecting both onto
// each edge normal: a gap on any axis means apart (a line fits between them); overlap on all
// of them gives the minimum translation vector, the shortest way out. One capsule joins in.
// Keys: drag a shape with the mouse, wheel turns it, Space pushes it out along the MTV,
// Tab holds the next shape, plus the shared keys (F1: outlines).
// Option: --spin DEGREES turns the held shape by itself, DEGREES a second.
#include "RotatedLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 6 - Rotated boxes", {"--spin"}},
                       [](const hitbox::Options& options)
                       {
                           auto level = std::make_unique<RotatedLevel>();
                           level->setSpin(
                               static_cast<float>(options.number("--spin", 0.0, -720.0, 720.0)));
                           return level;
                       });
}
