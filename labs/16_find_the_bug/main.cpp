// Lab 16 - Find the bug
// Teaches: debugging collisions with the tools a fixed, deterministic step allows: the
// contact timeline (--timeline) of enter and exit events, explain (F1: why a pair does or
// does not collide), and a recorded run replayed to the step where it goes wrong
// (--record, --replay, --pause-at-step). Three planted bugs, one a task, in Bugs.cpp.
// Keys: arrows move the gatekeeper, R restarts; plus F1 debug (the pair under the mouse
// explained), P pause, N step, F12 screenshot. The tasks are in README.md.
#include "DepotLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 16 - Find the bug"},
                       [](const hitbox::Options&) { return std::make_unique<DepotLevel>(); });
}
