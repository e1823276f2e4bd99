// Lab 8 - Many objects: from the n^2 pair table to a broadphase.
// Teaches: testing every pair costs n(n-1)/2 tests (the pair table); game rules (layers
// and masks) skip pairs before any geometry; a broadphase (sort and sweep, grid, quadtree)
// finds the few pairs worth testing, so 10,000 balls cost little more per ball than 100.
// Keys: Up/Down more or fewer balls   M next broadphase method
//       1 crowd   2 pair table   3 layers   plus the shared keys (F1 draws the grid/quadtree)
// Options: --balls N   --method brute|sweep|grid|quadtree   --scene crowd|table|layers
//          --print-timing SECONDS (print the readout to the terminal that often)
// e.g. lab08_many_objects --screenshot shot.png --balls 10000 --debug --frames 60
#include "ManyObjectsLevel.h"

#include "hitbox/app/App.h"

#include <memory>
#include <string>

int main(int argc, char* argv[])
{
    const hitbox::ProgramInfo info{"Lab 8 - Many objects",
                                   {"--balls", "--method", "--scene", "--print-timing"}};
    return hitbox::run(
        argc, argv, info,
        [](const hitbox::Options& options)
        {
            LabSettings settings;
            settings.scene = parseScene(options.get("--scene", "crowd"));
            const int defaultBalls = settings.scene == Scene::PairTable ? 12 : 1000;
            settings.balls = std::stoi(options.get("--balls", std::to_string(defaultBalls)));
            // The pair table is brute force; elsewhere the grid is the default.
            settings.method = parseMethod(
                options.get("--method", settings.scene == Scene::PairTable ? "brute" : "grid"));
            settings.seed = options.seed;
            settings.printTimingSeconds = std::stof(options.get("--print-timing", "0"));
            return std::make_unique<ManyObjectsLevel>(settings);
        });
}
