// Lab 11 - Pong: students build it
// Teaches: a whole game from the unit's ideas. Paddles kept inside the court, a ball that
// bounces off walls, a collisionResponse that returns the ball at an angle set by where it
// hit the paddle, score and serve, a swept ball that never passes through a moving paddle
// at any speed, and a computer opponent that can be beaten.
// Keys: W/S the left paddle; Up/Down the right one when C has handed it to a second player
// (C again gives it back to the computer); plus F1 debug boxes, P pause, N step, F12
// screenshot, Esc quit. Option: --players 0 (the computer plays both sides), 1 (you against
// the computer, the default) or 2. The numbers to play with are in Court.h; the tasks in
// README.md.
#include "PongLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 11 - Pong", {"--players"}},
                       [](const hitbox::Options& options)
                       {
                           return std::make_unique<PongLevel>(
                               options.seed,
                               static_cast<int>(options.wholeNumber("--players", 1, 0, 2)));
                       });
}
