// pong_record_match FILE [STEPS] - plays a two-player match of Pong with scripted keys for
// STEPS fixed steps (default 3000, 25 s: a match under way), writes it as a replay that
// `pong --replay FILE --headless` plays back, and prints the match's final state
// (PongLevel::describeState).
//
// scripts/same-runs.sh records on one SFML and replays on the other (scripts/ci-sfml3.sh):
// the replay must end in the same state line, byte for byte. The level is built as `pong
// --mode 2p --headless` builds it (pong/main.cpp), and the file says so.
#include "PongLevel.h"
#include "ScriptedInput.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Replay.h"
#include "hitbox/app/ReplayLevel.h"
#include "hitbox/app/WholeFile.h"

#include <exception>
#include <iostream>
#include <random>
#include <string>

namespace
{
const unsigned matchSeed = 7;  // --seed of the recorded run
const unsigned inputSeed = 11; // the scripted keys
} // namespace

int main(int argc, char* argv[])
{
    long long steps = 3000;
    try
    {
        if (argc == 3)
            steps = std::stoll(argv[2]);
    }
    catch (const std::exception&)
    {
        steps = -1;
    }
    if (argc < 2 || argc > 3 || steps < 1)
    {
        std::cerr << "usage: pong_record_match FILE [STEPS]   (STEPS a whole number, 1 or more)\n";
        return 2;
    }

    PongSettings settings;
    settings.seed = matchSeed;
    settings.mode = Mode::TwoPlayers;
    PongLevel pong(settings);
    pong.startMatch(Mode::TwoPlayers);
    hitbox::Recording header;
    header.program = "Pong";
    header.seed = matchSeed;
    header.headless = true;
    header.options = {{"--mode", "2p"}};
    hitbox::RecordingLevel recorder(pong, header);
    hitbox::Input input;
    std::mt19937 random(inputSeed);
    for (long long step = 0; step < steps; ++step)
    {
        pongtesting::scriptInput(input, random);
        recorder.handleInput(input, hitbox::stepSeconds);
        recorder.update(hitbox::stepSeconds);
        input.update();
    }
    const hitbox::SaveResult saved =
        hitbox::saveWholeFile(argv[1], hitbox::replayText(recorder.getRecording()));
    if (!saved)
    {
        std::cerr << "pong_record_match: " << saved.problem << "\n";
        return 1;
    }
    std::cout << pong.describeState() << "\n";
    return 0;
}
