// Lab 5 - Ray caster
// Teaches: casting a ray against many boxes and keeping the NEAREST hit (slab method), then
// moving a box with hitbox::moveBoxAndSlide (a sweep, then a slide along walls), and why the
// contacts of one step are handled in time order so the box does not snag on tile seams.
// Keys: mouse aims the ray, WASD/arrows move, T time order on/off, plus the shared keys.
// Option: --time-order off starts with the fix switched off (the "before" picture).
#include "RayLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 5 - Ray caster", {"--time-order"}},
                       [](const hitbox::Options& options)
                       {
                           auto level = std::make_unique<RayLevel>();
                           level->setTimeOrder(options.onOff("--time-order", true));
                           return level;
                       });
}
