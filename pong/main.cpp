// Pong - the Hitbox sample game: a complete game built on the framework.
// Teaches: GameObjects that collide, a swept ball that never tunnels through a paddle at any
// speed (BallPhysics.cpp), collision responses with a contact normal (Ball.cpp), and rules
// kept apart from drawing so a whole match runs in a test.
// Keys: title 1/2/3 choose the mode, D difficulty, Left/Right points to win;
// in play W/S (left) and Up/Down (right), M mute, Esc back to the title; plus the shared
// keys F1 debug boxes, P pause, N step, F12 screenshot.
// Command line: --mode 1p|2p|cvc  --difficulty easy|normal|hard  --points-to-win N
// --screen title|play|win, and the shared --headless --seconds --screenshot --seed.
#include "PongLevel.h"

#include "hitbox/app/App.h"

#include <memory>
#include <string>

namespace
{
std::unique_ptr<hitbox::Level> makePong(const hitbox::Options& options)
{
    PongSettings settings;
    settings.seed = options.seed;
    settings.difficulty =
        difficultyFromName(options.oneOf("--difficulty", "normal", {"easy", "normal", "hard"}));
    settings.pointsToWin = static_cast<int>(options.wholeNumber("--points-to-win", 11, 1, 99));
    // With no window nobody can press a key, so headless runs play computer vs computer.
    const std::string defaultMode = options.headless ? "cvc" : "1p";
    settings.mode = modeFromName(options.oneOf("--mode", defaultMode, {"1p", "2p", "cvc"}));
    auto pong = std::make_unique<PongLevel>(settings);

    const bool picture = !options.screenshotPath.empty();
    const std::string screen = options.oneOf("--screen", "", {"title", "play", "win"});
    if (screen == "title")
        pong->showTitle();
    else if (screen == "play")
        pong->startMatch(settings.mode);
    else if (screen == "win")
        pong->showWinScreen(settings.pointsToWin, settings.pointsToWin * 2 / 3);
    else if (picture)
    {
        // A picture with no screen named shows the attract mode, a few seconds into a rally
        // (unless --frames says how far).
        pong->startAttractMode();
        if (options.frames < 0)
            hitbox::simulate(*pong, 480);
    }
    else if (options.headless || options.extra.count("--mode") > 0)
        pong->startMatch(settings.mode); // a mode was chosen: skip the title
    if (!options.headless && !picture)
        pong->enableSound();
    return pong;
}
} // namespace

int main(int argc, char* argv[])
{
    return hitbox::run(
        argc, argv, {"Pong", {"--mode", "--difficulty", "--points-to-win", "--screen"}}, makePong);
}
