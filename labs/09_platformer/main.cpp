// Lab 9 - Platformer: a player against a tile level.
// Teaches: platformer movement in a fixed step (acceleration, braking, top speed, gravity,
// a jump only from the ground); collision points around the player tested against solid
// tiles in a fixed order; corners pushed out along the axis of least penetration; knowing
// when the player is grounded; the swept-bounds broad phase (only nearby tiles are tested);
// a speed cap against tunnelling, and speculative contacts as the other cure; one-way
// platforms, slopes (the foot follows the surface) and a checkpoint trigger.
// Keys: A/D or arrows run, Space/W jump, S dive (very fast, downwards), C speed cap on/off,
//       X speculative contacts on/off, R back to the last checkpoint, plus the shared keys
//       (F1 debug view).
// Options: --level levels/NAME.txt loads another level from assets/ (or a full path);
//          --demo on makes the player run right and jump by itself (lectures, screenshots).
#include "PlatformerLevel.h"

#include "hitbox/app/App.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace
{
// The level named on the command line: a missing or broken file is bad input (exit code 2).
TileMap loadLevel(const std::string& path)
{
    try
    {
        return TileMap::load(path);
    }
    catch (const hitbox::AssetError& error)
    {
        throw std::invalid_argument(error.what());
    }
}
} // namespace

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 9 - Platformer", {"--level", "--demo"}},
                       [](const hitbox::Options& options)
                       {
                           auto level = std::make_unique<PlatformerLevel>(
                               loadLevel(options.get("--level", "levels/platformer.txt")));
                           level->setDemo(options.onOff("--demo", false));
                           return level;
                       });
}
