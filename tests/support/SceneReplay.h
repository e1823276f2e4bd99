// SceneReplay.h - a grading test that runs a lab's scene the way its program does, writing
// down the input of every step (hitbox::RecordingLevel). When an assertion fails, the message
// carries the one command that opens the run in the window, paused at the failing step:
//
//     WorldLevel level(3);                              // what `lab15_world --seed 3` builds
//     RecordedScene scene(level, {"Lab 15 - Many objects in one World", 3});
//     for (int i = 0; i < 2400; ++i)
//     {
//         scene.step(input);
//         ASSERT_EQ(level.getScore(), expected) << scene.replayCommand();
//     }
//
// GoogleTest evaluates what follows << only when the assertion fails, so a passing test writes
// nothing; a failing one writes replays/SUITE.TEST.replay in the folder it runs in (ctest: the
// lab's test folder under build/) and says:
//     Watch it: "build/.../lab15_world" --replay "build/.../replays/X.Y.replay" --pause-at-step 812
// The level must be the one the program builds from `program` (title, --seed, its own
// options): the replay rebuilds it from those, not from the test.
#pragma once

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/ReplayLevel.h"
#include "hitbox/app/WholeFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#if __has_include("LabProgram.h") // generated for the labs' test targets (HitboxLab.cmake)
#include "LabProgram.h"
#else
#define HITBOX_LAB_PROGRAM "the lab's program"
#endif

namespace scenereplay
{

// How the program was started, so that `--replay` builds the same level.
struct SceneProgram
{
    std::string title; // the program's window title (its ProgramInfo), e.g. "Pong"
    unsigned seed = 1; // --seed
    std::map<std::string, std::string> options = {}; // its own options, e.g. {"--balls", "200"}
    std::string executable = HITBOX_LAB_PROGRAM;
};

class RecordedScene
{
public:
    RecordedScene(hitbox::Level& level, const SceneProgram& program)
        : recorder(level, header(program)), executable(program.executable)
    {
    }

    // One fixed step, exactly as the loop runs it: input, update, end of the frame.
    void step(hitbox::Input& input)
    {
        recorder.handleInput(input, hitbox::stepSeconds);
        recorder.update(hitbox::stepSeconds);
        input.update();
    }

    // Steps run so far; the step that just ran is number stepCount() - 1.
    [[nodiscard]] long long stepCount() const { return recorder.getStep(); }

    // Saves the run so far and returns the line that opens it, paused after the last step.
    [[nodiscard]] std::string replayCommand() const
    {
        namespace fs = std::filesystem;
        const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
        std::string name = test == nullptr
                               ? std::string("scene")
                               : std::string(test->test_suite_name()) + "." + test->name();
        for (char& c : name)
            if (c == '/' || c == '\\' || c == ':' || c == ' ')
                c = '_';
        std::error_code error;
        const fs::path folder = fs::absolute("replays", error);
        fs::create_directories(folder, error);
        const fs::path file = folder / (name + ".replay");
        const hitbox::SaveResult saved =
            hitbox::saveWholeFile(file.string(), hitbox::replayText(recorder.getRecording()));
        if (!saved)
            return "\n(the replay could not be saved as " + file.string() + ": " + saved.problem +
                   ")";
        return "\nWatch it: \"" + executable + "\" --replay \"" + file.string() +
               "\" --pause-at-step " + std::to_string(stepCount());
    }

private:
    static hitbox::Recording header(const SceneProgram& program)
    {
        hitbox::Recording recording;
        recording.program = program.title;
        recording.seed = program.seed;
        recording.headless = false;
        recording.options = program.options;
        return recording;
    }

    hitbox::RecordingLevel recorder;
    std::string executable;
};

} // namespace scenereplay
