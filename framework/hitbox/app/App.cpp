#include "hitbox/app/App.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Display.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/app/ReplayLevel.h"
#include "hitbox/app/SavePath.h"
#include "hitbox/app/WholeFile.h"
#include "hitbox/app/private/LongRun.h"
#include "hitbox/app/private/ScreenshotRun.h"
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
    const long long frames = options.frames >= 0 ? options.frames : headlessDefaultSteps;
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
    float secondsSinceLastFrame() override { return stepSeconds; }
    void processInput(Input&) override { --framesLeft; }
    int stepsToRun(int) override { return 1; }
    void render(const Level&, float) override {}

private:
    long long framesLeft;
};

int runLevel(Level& level, const Options& options, const ProgramInfo& info, RewindTools tools = {})
{
    if (options.headless)
        return runHeadless(level, options, info);
    if (!options.screenshotPath.empty())
        return saveScreenshot(level, options, info);
    return runWindow(level, options, info, tools);
}

// Reads --replay's file into `replay` and sets what the replay decides (how long to run,
// where to pause); false after printing the one line that says why it cannot be replayed.
bool prepareReplay(Options& options, const ProgramInfo& info, Recording& replay)
{
    ReplayRead read = readReplayFile(options.replayPath);
    if (read && read.recording.program != info.title)
        read = {false,
                {},
                "'" + printable(options.replayPath, 200) + "' was recorded by '" +
                    printable(read.recording.program) + "', not by this program"};
    if (read && !options.extra.empty())
        read = {false,
                {},
                "the program's own options come from the replay: leave out " +
                    options.extra.begin()->first};
    if (!read)
    {
        std::cerr << info.title << ": --replay: " << read.problem << std::endl;
        return false;
    }
    replay = read.recording;
    const bool window = !options.headless && options.screenshotPath.empty();
    if (options.frames < 0 && !window)
        options.frames = replay.steps;
    if (options.pauseAtStep < 0 && window)
        options.pauseAtStep = replay.steps;
    return true;
}

// Saves `text` as `path`, printing one line: what was saved, or why it could not be.
bool saveReporting(const ProgramInfo& info, const std::string& option, const std::string& path,
                   const std::string& text, const std::string& what)
{
    const SaveResult saved = saveWholeFile(path, text);
    if (!saved)
        std::cerr << info.title << ": " << option << ": could not save '" << printable(path, 200)
                  << "': " << saved.problem << std::endl;
    else
        std::cout << info.title << ": " << what << " in " << printable(path, 200) << std::endl;
    return static_cast<bool>(saved);
}

// The level the program makes, wrapped for --replay or --record, then --timeline
// (ReplayLevel.h), run as asked; the files are written only after a run that ended well.
int runRecordable(Options options, const ProgramInfo& info, const LevelFactory& makeLevel)
{
    Recording replay;
    if (!options.replayPath.empty() && !prepareReplay(options, info, replay))
        return 2;
    for (const auto& [option, path] :
         {std::pair<std::string, std::string>{"--record", options.recordPath},
          {"--timeline", options.timelinePath}})
    {
        const SaveResult writable = path.empty() ? SaveResult{true, ""} : checkSavePath(path);
        if (!writable)
        {
            std::cerr << info.title << ": " << option << ": cannot save '" << printable(path, 200)
                      << "': " << writable.problem << std::endl;
            return 2;
        }
    }
    Options levelOptions = options;
    if (!options.replayPath.empty())
    {
        // The level is built exactly as it was when recorded.
        levelOptions.seed = replay.seed;
        levelOptions.extra = replay.options;
        levelOptions.headless = replay.headless;
    }
    std::unique_ptr<Level> made = makeLevel(levelOptions);
    // In the window, the rewind sits right around the level (Rewind.h: looking back never
    // changes what the replay, the recording or the timeline see).
    const bool window = !options.headless && options.screenshotPath.empty();
    std::unique_ptr<RewindLevel> rewind = window ? std::make_unique<RewindLevel>(*made) : nullptr;
    Level* level = rewind ? rewind.get() : made.get();
    std::unique_ptr<ReplayingLevel> replaying;
    std::unique_ptr<RecordingLevel> recorder;
    Level* inner = level;
    if (!options.replayPath.empty())
        inner = (replaying = std::make_unique<ReplayingLevel>(*level, replay)).get();
    else if (!options.recordPath.empty())
    {
        Recording header;
        header.program = info.title;
        header.seed = options.seed;
        header.headless = options.headless;
        header.options = options.extra;
        inner = (recorder = std::make_unique<RecordingLevel>(*level, header)).get();
    }
    std::unique_ptr<TimelineLevel> timeline;
    if (!options.timelinePath.empty() || window) // the window's rewind strip shows it
        timeline = std::make_unique<TimelineLevel>(*inner);
    const int code = runLevel(timeline ? *timeline : *inner, options, info,
                              {rewind.get(), timeline ? &timeline->getTimeline() : nullptr});
    if (code != 0)
        return code; // a run stopped by Ctrl-C or an error leaves no half-written file

    if (recorder &&
        !saveReporting(info, "--record", options.recordPath, replayText(recorder->getRecording()),
                       "recorded " + std::to_string(recorder->getStep()) + " steps"))
        return 1;
    if (timeline && !options.timelinePath.empty() &&
        !saveReporting(info, "--timeline", options.timelinePath,
                       timelineCsv(timeline->getTimeline().getEvents()),
                       std::to_string(timeline->getTimeline().getEvents().size()) +
                           " contact events"))
        return 1;
    return 0;
}

} // namespace

void simulate(Level& level, long long frames)
{
    HeadlessHost host(frames);
    runLoop(level, host);
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
        return runRecordable(options, info, makeLevel);
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
