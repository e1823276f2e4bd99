// Lab 7 - Swept circles
// Teaches: finding collisions by time of impact. Each step, the first collision (ball-ball
// from the quadratic (Ericson, 5.5), ball-cushion from the rounded box) is found, everything
// moves up to it, it is answered with an elastic bounce, and the rest of the step goes round
// again: a ball at any speed hits the ball in its way. D switches to the discrete version.
// Keys: click/Space shoot at the mouse, Up/Down shot speed, D discrete/swept, R rack again,
// plus the shared keys. Option: --mode discrete starts with the discrete version ("before").
#include "PoolLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(
        argc, argv, {"Lab 7 - Swept circles", {"--mode"}},
        [](const hitbox::Options& options)
        {
            auto level = std::make_unique<PoolLevel>();
            level->setSwept(options.oneOf("--mode", "swept", {"swept", "discrete"}) == "swept");
            return level;
        });
}
