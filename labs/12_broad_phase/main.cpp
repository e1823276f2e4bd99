// Lab 12 - The broad phase by hand
// Teaches: why testing every pair stops scaling, and three ways to test fewer: sort and
// sweep along x, a uniform grid, and a cheap bounding box before an exact circle test.
// Keys: M switches brute force, sort and sweep and the grid (the readout counts the exact
// tests); plus P pause, N step, F12 screenshot. Options: --boxes N (default 300).
// The tasks are in README.md.
#include "CrowdLevel.h"

#include "hitbox/app/App.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace
{
int boxCountFrom(const hitbox::Options& options)
{
    const std::string text = options.get("--boxes", "300");
    try
    {
        const int count = std::stoi(text);
        if (count >= 0 && count <= 20000)
            return count;
    }
    catch (const std::exception&)
    {
    }
    throw std::invalid_argument(
        "--boxes needs a whole number from 0 to 20000, e.g. --boxes 500 (not '" + text + "')");
}
} // namespace

int main(int argc, char* argv[])
{
    return hitbox::run(argc, argv, {"Lab 12 - The broad phase by hand", {"--boxes"}},
                       [](const hitbox::Options& options) {
                           return std::make_unique<CrowdLevel>(boxCountFrom(options), options.seed);
                       });
}
