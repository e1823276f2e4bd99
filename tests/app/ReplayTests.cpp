// Record and replay (Replay.h, Csv.h, WholeFile.h): the input a step saw comes back exactly,
// the file format round-trips, and every bad file is refused with one line naming the row.
#include "support/CommandLine.h"

#include "hitbox/app/Csv.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Keys.h"
#include "hitbox/app/Replay.h"
#include "hitbox/app/SavePath.h"
#include "hitbox/app/WholeFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

// Every state one key can be in after a frame of events, reached through Input's setters.
std::vector<hitbox::Input> everyKeyState(int key)
{
    std::vector<hitbox::Input> states;
    const std::vector<std::vector<bool>> scripts = {
        {}, {true}, {true, false}, {true, false, true}, {false}, {true, false, true, false}};
    for (bool heldBefore : {false, true})
        for (const std::vector<bool>& script : scripts)
        {
            hitbox::Input input;
            if (heldBefore)
            {
                input.setKeyDown(key);
                input.setMouseLDown(true);
                input.update();
            }
            for (bool down : script)
            {
                down ? input.setKeyDown(key) : input.setKeyUp(key);
                input.setMouseLDown(down);
            }
            states.push_back(input);
        }
    return states;
}

} // namespace

TEST(Replay, EveryKeyAndButtonStateComesBackThroughASnapshot)
{
    for (int key : {0, static_cast<int>(sf::Keyboard::Key::Space), hitbox::keyCount - 1})
        for (const hitbox::Input& input : everyKeyState(key))
        {
            const hitbox::InputSnapshot snapshot = hitbox::captureInput(input);
            const hitbox::Input back = hitbox::restoreInput(snapshot);
            EXPECT_EQ(back.isKeyDown(key), input.isKeyDown(key));
            EXPECT_EQ(back.isPressed(key), input.isPressed(key));
            EXPECT_EQ(back.isReleased(key), input.isReleased(key));
            EXPECT_EQ(back.isLeftMouseDown(), input.isLeftMouseDown());
            EXPECT_EQ(back.isLeftMousePressed(), input.isLeftMousePressed());
            EXPECT_EQ(back.isLeftMouseReleased(), input.isLeftMouseReleased());
            EXPECT_TRUE(hitbox::sameInput(hitbox::captureInput(back), snapshot));
        }
}

TEST(Replay, TheFileRoundTripsEveryFieldBitForBit)
{
    hitbox::Recording recording;
    recording.program = "Lab 8 - Many objects, \"quoted\"";
    recording.seed = 4294967295u;
    recording.headless = true;
    recording.options = {{"--balls", "10000"}, {"--scene", "a,b"}};
    hitbox::Input input;
    recording.addStep(hitbox::captureInput(input)); // step 0: nothing, so no row
    input.setKeyDown(sf::Keyboard::Key::W);
    input.setMousePosition(sf::Vector2f(0.1f, -1e-39f)); // a denormal, too
    input.addMouseWheel(std::nextafter(1.f, 2.f));
    recording.addStep(hitbox::captureInput(input));
    recording.addStep(hitbox::captureInput(input)); // same input: no new row
    input.update();
    recording.addStep(hitbox::captureInput(input));

    const std::string text = hitbox::replayText(recording);
    const hitbox::ReplayRead read = hitbox::readReplayText(text);
    ASSERT_TRUE(read) << read.problem;
    EXPECT_EQ(read.recording.program, recording.program);
    EXPECT_EQ(read.recording.seed, recording.seed);
    EXPECT_TRUE(read.recording.headless);
    EXPECT_EQ(read.recording.options, recording.options);
    EXPECT_EQ(read.recording.steps, 4);
    ASSERT_EQ(read.recording.changes.size(), 2u);
    for (long long step = 0; step < 4; ++step)
        EXPECT_TRUE(hitbox::sameInput(read.recording.inputAt(step), recording.inputAt(step)))
            << "step " << step;
    EXPECT_TRUE(read.recording.inputAt(2).keysPressed.size() == 1);
    EXPECT_TRUE(read.recording.inputAt(3).keysPressed.empty());
    EXPECT_EQ(hitbox::replayText(read.recording), text);
}

TEST(Replay, ABadFileIsRefusedNamingTheRowAndWhy)
{
    const std::string head = "hitbox-replay,1\nprogram,P\nseed,1\nheadless,no\nsteps,10\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"", "the file is empty"},
        {"hello,1\n", "row 1: not a Hitbox replay"},
        {"hitbox-replay,2\n", "row 1: a replay of format 2; this Hitbox reads format 1"},
        {"hitbox-replay,1\nprogram,P\n", "it has no 'seed' row"},
        {head + "seed,2\n", "row 6: 'seed' is given twice"},
        {head + "input,3,,,,0,0,,,0\ninput,3,,,,0,0,,,0\n", "row 7: input rows must come in order"},
        {head + "input,10,,,,0,0,,,0\n", "an input row is for a step after the last"},
        {head + "input,1,999,,,0,0,,,0\n", "row 6: a key code needs a whole number from 0"},
        {head + "input,1,,,,x,0,,,0\n", "row 6: the mouse's x needs a number, not 'x'"},
        {head + "input,1,,,,0,0,pd,,0\n", "row 6: a mouse button needs its flags d, p, r"},
        {head + "input,1,,,,0,0\n", "row 6: a 'input' row has 10 fields, this one 7"},
        {head + "wobble,1\n", "row 6: unknown row 'wobble'"},
        {head + "option,\"--a,1\n", "row 6: a quoted field is never closed"},
        {"hitbox-replay,1\nprogram,P\nseed,-1\nheadless,no\nsteps,1\n",
         "row 3: seed needs a whole number from 0 to 4294967295, not '-1'"},
    };
    for (const auto& [text, message] : cases)
    {
        const hitbox::ReplayRead read = hitbox::readReplayText(text);
        EXPECT_FALSE(read) << text;
        EXPECT_NE(read.problem.find(message), std::string::npos)
            << "for:\n"
            << text << "\ngot: " << read.problem;
        EXPECT_EQ(read.problem.find('\n'), std::string::npos) << "one line: " << read.problem;
    }
}

TEST(Csv, QuotesOnlyWhatNeedsItAndReadsItBack)
{
    std::ostringstream out;
    hitbox::CsvWriter csv(out);
    const std::vector<std::string> fields = {"plain", "", "a,b", "say \"hi\"", "two\r\nlines"};
    csv.row(fields);
    csv.row({"x"});
    EXPECT_EQ(out.str(), "plain,,\"a,b\",\"say \"\"hi\"\"\",\"two\r\nlines\"\r\nx\r\n");
    std::istringstream in(out.str());
    std::vector<std::string> row;
    std::string problem;
    ASSERT_TRUE(hitbox::readCsvRow(in, row, problem));
    EXPECT_EQ(row, fields);
    ASSERT_TRUE(hitbox::readCsvRow(in, row, problem));
    EXPECT_EQ(row, std::vector<std::string>{"x"});
    EXPECT_FALSE(hitbox::readCsvRow(in, row, problem));
    EXPECT_TRUE(problem.empty());
}

TEST(Csv, ExactTextReadsBackTheSameFloatIncludingTheEdges)
{
    for (float value : {0.f, -0.f, 0.1f, 1.f / 3.f, 1e-45f, -3.4028235e38f,
                        std::numeric_limits<float>::infinity(), 123456.789f})
    {
        float back = 42.f;
        ASSERT_TRUE(hitbox::readExact(hitbox::exactText(value), back)) << value;
        EXPECT_EQ(std::signbit(back), std::signbit(value));
        EXPECT_EQ(back, value);
    }
    float back = 0.f;
    EXPECT_TRUE(hitbox::readExact(hitbox::exactText(std::nanf("")), back));
    EXPECT_TRUE(std::isnan(back));
    EXPECT_FALSE(hitbox::readExact("1.5x", back));
    EXPECT_FALSE(hitbox::readExact("", back));
}

TEST(WholeFile, SavesCompleteFilesAndRefusesFoldersWithoutLeavingAnything)
{
    namespace fs = std::filesystem;
    const fs::path folder = fs::temp_directory_path() / "hitbox-wholefile-test";
    fs::remove_all(folder);
    fs::create_directories(folder);
    const fs::path file = folder / "run.replay";
    ASSERT_TRUE(hitbox::saveWholeFile(file.string(), "first"));
    ASSERT_TRUE(hitbox::saveWholeFile(file.string(), "second"));
    std::ifstream in(file);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "second");
    EXPECT_FALSE(hitbox::saveWholeFile(folder.string(), "x"));
    const std::string missing = hitbox::checkSavePath((folder / "no" / "x").string()).problem;
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    int files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++files;
    EXPECT_EQ(files, 1) << "no temporary file is left behind";
    fs::remove_all(folder);
}

TEST(Options, RecordReplayAndPauseAtStepAreReadAndTheirClashesRefused)
{
    const hitbox::Options options =
        parseCommandLine({"--replay", "a.replay", "--pause-at-step", "12"});
    EXPECT_EQ(options.replayPath, "a.replay");
    EXPECT_EQ(options.pauseAtStep, 12);
    EXPECT_EQ(parseCommandLine({"--record", "b"}).recordPath, "b");
    EXPECT_THROW(parseCommandLine({"--record", "a", "--replay", "b"}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--headless", "--pause-at-step", "3"}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--record", ""}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--pause-at-step", "-1"}), std::invalid_argument);
}
