// Lab 1 - Point in box
// Teaches: testing a point against an axis-aligned box (the mouse against each box), and
// why the mouse must be in the same coordinates as the boxes before you test it.
// Keys: move the mouse over the boxes, hold the left button to drag one, mouse wheel or
// +/- to zoom, 0 to reset the zoom; plus F1 debug boxes, P pause, N step, F12 screenshot.
// The tasks are in README.md.
#include "PointInBoxLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 1 - Point in box"},
                       [](const hitbox::Options&) { return std::make_unique<PointInBoxLevel>(); });
}
