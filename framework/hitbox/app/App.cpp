#include "hitbox/app/App.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Display.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/app/private/LongRun.h"
#include "hitbox/app/private/Window.h"
#include "hitbox/platform/SilentAudio.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace hitbox
{
namespace
{

int runHeadless(Level& level, const Options& options, const ProgramInfo& info)
{
    const long long frames = options.frames >= 0 ? options.frames : 600;
    if (!simulateReporting(level, frames, info.title))
        return stoppedExitCode;
    std::cout << info.title << ": " << frames << " frames, " << frames * stepSeconds
              << " s simulated | " << level.describeState() << std::endl;
    return 0;
}

// The loop's host without a window: no input, nothing drawn, exactly one step per frame.
class HeadlessHost : public LoopHost
{
public:
    explicit HeadlessHost(long long frames) : framesLeft(frames) {}

    bool isRunning() const override { return framesLeft > 0; }
    float processInput(Input&) override
    {
        --framesLeft;
        return stepSeconds;
    }
    int stepsToRun(int) override { return 1; }
    void render(const Level&) override {}

private:
    long long framesLeft;
};

} // namespace

void simulate(Level& level, long long frames)
{
    HeadlessHost host(frames);
    runLoop(level, host);
}

sf::Vector2u fitInside(sf::Vector2f size, sf::Vector2u limit)
{
    const double width = size.x >= 1.f ? static_cast<double>(size.x) : 1.0;
    const double height = size.y >= 1.f ? static_cast<double>(size.y) : 1.0;
    const double wide = std::max(1u, limit.x);
    const double tall = std::max(1u, limit.y);
    const double scale = std::min({1.0, wide / width, tall / height});
    auto side = [](double pixels, double most)
    { return static_cast<unsigned>(std::clamp(std::floor(pixels), 1.0, most)); };
    return {side(width * scale, wide), side(height * scale, tall)};
}

sf::FloatRect letterboxViewport(sf::Vector2u windowSize, sf::Vector2f worldSize)
{
    if (windowSize.x == 0 || windowSize.y == 0 || !(worldSize.x > 0.f) || !(worldSize.y > 0.f))
        return sf::FloatRect({0.f, 0.f}, {1.f, 1.f});
    const float windowAspect = static_cast<float>(windowSize.x) / static_cast<float>(windowSize.y);
    const float worldAspect = worldSize.x / worldSize.y;
    if (windowAspect > worldAspect)
    {
        // Window too wide: bars left and right.
        const float width = worldAspect / windowAspect;
        return sf::FloatRect({(1.f - width) / 2.f, 0.f}, {width, 1.f});
    }
    // Window too tall: bars above and below.
    const float height = windowAspect / worldAspect;
    return sf::FloatRect({0.f, (1.f - height) / 2.f}, {1.f, height});
}

int run(int argc, char* argv[], const ProgramInfo& info, const LevelFactory& makeLevel)
{
    Options options;
    try
    {
        options = parseOptions(argc, argv, info);
    }
    catch (const std::invalid_argument& error)
    {
        std::cerr << info.title << ": " << error.what() << std::endl;
        return 2;
    }
    if (options.help)
    {
        std::cout << usagePage(info);
        return 0;
    }
    const DisplayCheck display =
        options.headless ? DisplayCheck{true, "", nullptr} : checkDisplay();
    if (!display.available)
    {
        // SFML aborts (uncatchably) if it opens a window with no display: check first.
        std::cerr << info.title << ": no display found (" << display.reason
                  << "). Run with --headless --frames N to simulate without "
                     "a window, or start it under a display (e.g. xvfb-run -a).\n";
        return 2;
    }
    // Before the level makes its first sound: with no sound device, one line and silence
    // instead of an OpenAL error for every sound (SFML 2; issue 25, finding 26). Headless
    // runs are silent anyway, so they say nothing about it.
    const auto silent = platform::silenceAudioWithoutDevice();
    if (silent && !options.headless)
        std::cerr << info.title << ": " << *silent << '\n';
    try
    {
        std::unique_ptr<Level> level = makeLevel(options);
        if (options.headless)
            return runHeadless(*level, options, info);
        if (!options.screenshotPath.empty())
            return saveScreenshot(*level, options, info);
        return runWindow(*level, options, info);
    }
    catch (const std::invalid_argument& error)
    {
        // A level rejected the value of one of its own options (e.g. --mode sideways).
        std::cerr << info.title << ": " << error.what() << std::endl;
        return 2;
    }
    catch (const std::exception& error)
    {
        std::cerr << info.title << ": " << error.what() << std::endl;
        return 1;
    }
}

} // namespace hitbox
