// Lab 2 - Bouncing balls
// Teaches: the bounding-circle test (no square root needed), and a collision response that
// bounces two balls apart like billiard balls: separate them, then exchange their speeds
// along the line between their centres.
// Keys: Space adds a ball, R goes back to two balls; plus F1 debug circles and velocity
// arrows, P pause, N step, F12 screenshot. Option: --balls N starts with N balls.
// The tasks are in README.md.
#include "BallsLevel.h"

#include "hitbox/app/App.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace
{
int ballCountFrom(const hitbox::Options& options)
{
    const std::string text = options.get("--balls", "2");
    try
    {
        return std::stoi(text);
    }
    catch (const std::exception&)
    {
        throw std::invalid_argument("--balls needs a whole number, e.g. --balls 12 (not '" + text +
                                    "')");
    }
}
} // namespace

int main(int argc, char* argv[])
{
    return hitbox::run(
        argc, argv, {"Lab 2 - Bouncing balls", {"--balls"}},
        [](const hitbox::Options& options)
        { return std::make_unique<BallsLevel>(ballCountFrom(options), options.seed); });
}
