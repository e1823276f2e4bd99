// Lab 12 - The broad phase by hand
// Teaches: why testing every pair stops scaling, and three ways to test fewer: sort and
// sweep along x, a uniform grid, and a cheap bounding box before an exact circle test.
// Keys: M switches brute force, sort and sweep and the grid (the readout counts the exact
// tests); plus F1 debug view (sort and sweep: the sweep line and its open boxes), P pause,
// N step, F12 screenshot. Options: --boxes N (default 300).
// The tasks are in README.md.
#include "CrowdLevel.h"

#include "hitbox/app/App.h"

#include <memory>

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 12 - The broad phase by hand", {"--boxes"}},
                       [](const hitbox::Options& options)
                       {
                           const auto boxes = options.wholeNumber("--boxes", 300, 0, 20000);
                           return std::make_unique<CrowdLevel>(static_cast<int>(boxes),
                                                               options.seed);
                       });
}
