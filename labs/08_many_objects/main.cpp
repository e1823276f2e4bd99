// Lab 8 - Many objects: from the n^2 pair table to a broadphase.
// Teaches: testing every pair costs n(n-1)/2 tests (the pair table); game rules (layers
// and masks) skip pairs before any geometry; a broadphase (sort and sweep, grid, quadtree)
// finds the few pairs worth testing, so 10,000 balls cost little more per ball than 100.
// Keys: Up/Down more or fewer balls   M next broadphase method
//       1 crowd   2 pair table   3 layers   plus the shared keys (F1 draws the grid/quadtree)
// Options: --balls N   --method brute|sweep|grid|quadtree   --scene crowd|table|layers
//          --print-timing SECONDS (every SECONDS of simulated time, print the CPU time per
//          step: median, p99, max, and the broadphase / exact tests / response shares)
//          --threads 1|2 (the grid's threads; both give the same balls)
// e.g. lab08_many_objects --screenshot shot.png --balls 10000 --debug --frames 60
#include "ManyObjectsLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    const hitbox::ProgramInfo info{
        "Lab 8 - Many objects", {"--balls", "--method", "--scene", "--print-timing", "--threads"}};
    return hitbox::run(
        argc, argv, info,
        [](const hitbox::Options& options)
        {
            LabSettings settings;
            settings.scene =
                parseScene(options.oneOf("--scene", "crowd", {"crowd", "table", "layers"}));
            const bool table = settings.scene == Scene::PairTable;
            settings.balls =
                static_cast<int>(options.wholeNumber("--balls", table ? 12 : 1000, 1, maxBalls));
            // The pair table is brute force; elsewhere the grid is the default.
            settings.method = parseMethod(options.oneOf("--method", table ? "brute" : "grid",
                                                        {"brute", "sweep", "grid", "quadtree"}));
            settings.seed = options.seed;
            settings.threads = static_cast<int>(options.wholeNumber("--threads", 2, 1, 2));
            settings.printTimingSeconds =
                static_cast<float>(options.number("--print-timing", 0.0, 0.0, 3600.0));
            // The slow-step guard reads the wall clock: only where someone is watching.
            settings.stopWhenTooSlow = !options.headless && options.screenshotPath.empty();
            settings.showTimings = !options.repeatablePicture();
            return std::make_unique<ManyObjectsLevel>(settings);
        });
}
