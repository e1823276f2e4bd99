// --record and --replay on a real game: a 2-player match driven by scripted keys and mouse,
// written down, read back and replayed with no input at all, ends in the same state bit for
// bit (Replay.h). The replay gets nothing but the file's text.
#include "PongLevel.h"
#include "ScriptedInput.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/ReplayLevel.h"
#include "hitbox/app/Rewind.h"

#include <gtest/gtest.h>

#include <ios>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{

const long long steps = 6000; // 50 simulated seconds: several points, serves and bounces

PongSettings twoPlayers()
{
    PongSettings settings;
    settings.mode = Mode::TwoPlayers;
    settings.seed = 42;
    return settings;
}

// Every float that makes up the match's state, written exactly (hexadecimal floating point
// keeps every bit of a finite float, and tells -0 from 0): equal means bit-exact.
std::string stateBits(const PongLevel& pong)
{
    std::string bits;
    auto add = [&bits](float value)
    {
        std::ostringstream exact;
        exact << std::hexfloat << value << ' ';
        bits += exact.str();
    };
    for (const hitbox::GameObject* object :
         {static_cast<const hitbox::GameObject*>(&pong.getBall()),
          static_cast<const hitbox::GameObject*>(&pong.getPaddle(Side::Left)),
          static_cast<const hitbox::GameObject*>(&pong.getPaddle(Side::Right))})
    {
        add(object->getPosition().x);
        add(object->getPosition().y);
        add(object->getVelocity().x);
        add(object->getVelocity().y);
    }
    bits += std::to_string(pong.getScore().pointsOf(Side::Left)) + ":" +
            std::to_string(pong.getScore().pointsOf(Side::Right)) + ":" +
            std::to_string(pong.getStepCount()) + ":" + std::to_string(pong.getPaddleHitsTotal());
    return bits;
}

using pongtesting::scriptInput;

} // namespace

TEST(PongReplay, ARecordedMatchAndItsReplayEndBitForBitTheSame)
{
    PongLevel recorded(twoPlayers());
    recorded.startMatch(Mode::TwoPlayers);
    hitbox::Recording header;
    header.program = "Pong";
    hitbox::RecordingLevel recorder(recorded, header);
    hitbox::Input input;
    std::mt19937 random(7);
    for (long long i = 0; i < steps; ++i)
    {
        scriptInput(input, random);
        recorder.handleInput(input, hitbox::stepSeconds);
        recorder.update(hitbox::stepSeconds);
        input.update();
    }
    const std::string text = hitbox::replayText(recorder.getRecording());

    const hitbox::ReplayRead read = hitbox::readReplayText(text);
    ASSERT_TRUE(read) << read.problem;
    PongLevel replayed(twoPlayers());
    replayed.startMatch(Mode::TwoPlayers);
    hitbox::ReplayingLevel replaying(replayed, read.recording);
    hitbox::simulate(replaying, steps); // the loop with no input at all: only the file's

    EXPECT_GT(recorded.getPaddleHitsTotal(), 0) << "the script should have played some rallies";
    EXPECT_EQ(stateBits(replayed), stateBits(recorded));
    EXPECT_EQ(replayed.getBall().getPosition(), recorded.getBall().getPosition());

    // And the input matters: the same match without it ends elsewhere (so the check can fail).
    PongLevel unplayed(twoPlayers());
    unplayed.startMatch(Mode::TwoPlayers);
    hitbox::simulate(unplayed, steps);
    EXPECT_NE(stateBits(unplayed), stateBits(recorded));
}

TEST(PongRewind, EveryKeptStepOfAMatchIsShownAsItWasAndTheMatchGoesOnUnchanged)
{
    PongLevel reference(twoPlayers());
    reference.startMatch(Mode::TwoPlayers);
    PongLevel rewound(twoPlayers());
    rewound.startMatch(Mode::TwoPlayers);
    hitbox::RewindLevel rewind(rewound);
    std::vector<std::string> history{stateBits(reference)};
    hitbox::Input referenceInput;
    hitbox::Input input;
    std::mt19937 referenceRandom(3);
    std::mt19937 random(3);
    const long long run = 2000;
    for (long long i = 0; i < run; ++i)
    {
        scriptInput(referenceInput, referenceRandom);
        reference.handleInput(referenceInput, hitbox::stepSeconds);
        reference.update(hitbox::stepSeconds);
        referenceInput.update();
        history.push_back(stateBits(reference));
        scriptInput(input, random);
        rewind.handleInput(input, hitbox::stepSeconds);
        rewind.update(hitbox::stepSeconds);
        input.update();
    }
    ASSERT_TRUE(rewind.canRewind());
    EXPECT_EQ(rewind.oldestStep(), run - hitbox::rewindSteps);
    for (long long at : {run - 1, run - 2, rewind.oldestStep(), run - 600, run - 599, run})
    {
        ASSERT_EQ(rewind.show(at), at);
        EXPECT_EQ(stateBits(rewound), history[static_cast<std::size_t>(at)]) << "step " << at;
    }
    rewind.show(run - 700);
    scriptInput(referenceInput, referenceRandom);
    reference.handleInput(referenceInput, hitbox::stepSeconds);
    reference.update(hitbox::stepSeconds);
    scriptInput(input, random);
    rewind.handleInput(input, hitbox::stepSeconds); // a live step: back to the newest first
    rewind.update(hitbox::stepSeconds);
    EXPECT_EQ(stateBits(rewound), stateBits(reference));
}
