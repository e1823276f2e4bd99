// Lab 10 - Top-down: walls, trees and slimes seen from above (a Zelda-like).
// Teaches: a hitbox smaller than the sprite (only the feet collide); per-axis
// move-then-resolve, so walking diagonally into a wall slides along it; enemies that
// notice the player inside one circle and attack inside a smaller one; knockback and
// invulnerability time after a hit (blinking); drawing in order of the feet's y so
// whoever is nearer covers whoever is behind.
// Keys: WASD or arrows walk, Space swings the sword, R restarts, plus the shared keys
//       (F1 shows hitboxes, sprite boxes, notice and attack circles).
#include "TopDownLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 10 - Top-down"},
                       [](const hitbox::Options&) { return std::make_unique<TopDownLevel>(); });
}
