// Lab 15 - Many objects in one World
// Teaches: hitbox::World, the four steps of collision handling in one call: layers and
// masks decide which pairs may ever meet, the broadphase finds the candidates, a game rule
// vetoes pairs before the exact test, and collisionResponse tells both objects. Also who
// owns what: the level owns the objects, the World only points at them.
// Keys: arrows move the player (A gives the autopilot back), M switches the broadphase
// method, R restarts; plus F1 debug (the broadphase's cells, nodes or sweep bars, and every
// collision shape), P pause, N step, F12 screenshot. The tasks are in README.md.
#include "WorldLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 15 - Many objects in one World"},
                       [](const hitbox::Options& options)
                       { return std::make_unique<WorldLevel>(options.seed); });
}
