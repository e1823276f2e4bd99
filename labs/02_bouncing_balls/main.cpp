// Lab 2 - Bouncing balls
// Teaches: the bounding-circle test (no square root needed), and a collision response that
// bounces two balls apart like billiard balls: separate them, then exchange their speeds
// along the line between their centres.
// Keys: Space adds a ball, R goes back to two balls; plus F1 debug circles and velocity
// arrows, P pause, N step, F12 screenshot. Option: --balls N starts with N balls.
// The tasks are in README.md.
#include "BallsLevel.h"

#include "hitbox/app/App.h"

#include <memory>
int main(int argc, char* argv[])
{
    return hitbox::run(
        argc, argv, {"Lab 2 - Bouncing balls", {"--balls"}},
        [](const hitbox::Options& options)
        {
            return std::make_unique<BallsLevel>(
                static_cast<int>(options.wholeNumber("--balls", 2, 2, BallsLevel::maxBalls)),
                options.seed);
        });
}
