// Lab 0 - Your own Collision class
// Teaches: the three tests the whole unit starts from, written by you: box against box
// (and a point in a box), bounding circle against bounding circle, and a circle against a
// box by the closest point; on objects with origins, scales, rotations and collision boxes
// smaller than their pictures, and with Hitbox's edge rule: touching never collides.
// Keys: the mouse moves the probe, Space switches it between a ball and a box; plus F1
// your world boxes and circles, P pause, N step, F12 screenshot.
// The tasks are in README.md.
#include "ShapesLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 0 - Your own Collision class"},
                       [](const hitbox::Options&) { return std::make_unique<ShapesLevel>(); });
}
