// Lab 3 - Bouncing squares
// Teaches: axis-aligned bounding boxes (AABB), and why a sprite's collision box is set by
// hand: the picture has a see-through margin, and only the solid crate in the middle of
// it should collide. F1 shows the collision boxes over the pictures.
// Keys: Space adds a square, R goes back to two squares; plus F1 debug boxes, P pause,
// N step, F12 screenshot. Option: --squares N starts with N squares.
// The tasks are in README.md.
#include "SquaresLevel.h"

#include "hitbox/app/App.h"

#include <memory>
int main(int argc, char* argv[])
{
    return hitbox::run(
        argc, argv, {"Lab 3 - Bouncing squares", {"--squares"}},
        [](const hitbox::Options& options)
        {
            return std::make_unique<SquaresLevel>(
                static_cast<int>(options.wholeNumber("--squares", 2, 2, SquaresLevel::maxSquares)),
                options.seed);
        });
}
