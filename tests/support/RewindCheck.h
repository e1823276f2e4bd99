// RewindCheck.h - the check that a program's level rewinds exactly (hitbox::RewindLevel,
// framework/hitbox/app/Rewind.h). The level runs inside a RewindLevel beside a copy that never
// rewinds, both fed the same scripted input. Paused after each step in `pauses`, every kept
// step is shown going back to the oldest, then going forward again, then a few jumps; each
// shown step must equal the same step of the run that never rewound, bit for bit: its state
// (`state`: every value a step changes, as exact text; and the help and state lines the window
// shows) and the contact events of that step
// (as --timeline writes them: a pair in contact where the re-simulation begins must go on with
// Stay and its Exit, never a second Enter). Then the live run goes on and must stay equal to
// the other one, step by step, to the end.
#pragma once

#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/app/Rewind.h"
#include "hitbox/app/Timeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rewindcheck
{

struct Program
{
    hitbox::LevelMaker make; // builds the level as the program does (seed, options)
    std::function<std::string(const hitbox::Level&)> state;        // every value a step changes
    std::function<void(hitbox::Input&, long long step)> keys = {}; // the input before `step`
};

// What the check saw, so a test can assert that its scene had something to lose.
struct Seen
{
    long long stepsShown = 0;
    int enters = 0; // contact events among the kept steps that were shown
    int stays = 0;
    int exits = 0;
    bool rebuilt = false; // shown by a rebuilt level (RewindReplay.h), not a restored one
};

// The step's contact events as --timeline's rows (names and exact numbers, no pointers).
inline std::string eventsText(long long step, const std::vector<hitbox::PairEvent>& events)
{
    hitbox::Timeline timeline;
    timeline.addStep(step, events);
    return hitbox::timelineCsv(timeline.getEvents());
}

// The state, and what the window writes of it: the help line and the state line, asked of
// `drawn` (the RewindLevel: they must come from the step shown, not the live one).
inline std::string shownText(const Program& program, const hitbox::Level& level,
                             const hitbox::Level& drawn)
{
    return program.state(level) + "\nhelp: " + drawn.getHelpText() +
           "\nstate: " + drawn.describeState();
}

inline Seen checkRewind(const Program& program, long long steps,
                        const std::vector<long long>& pauses, long long kept)
{
    Seen seen;
    std::unique_ptr<hitbox::Level> reference = program.make();
    std::unique_ptr<hitbox::Level> live = program.make();
    hitbox::RewindLevel rewind(*live, program.make, kept);
    seen.rebuilt = rewind.rebuilds();
    std::vector<std::string> states{shownText(program, *reference, *reference)};
    std::vector<std::string> events{eventsText(0, {})};
    hitbox::Input referenceInput;
    hitbox::Input input;
    const auto check = [&](long long at)
    {
        EXPECT_EQ(rewind.show(at), at);
        const auto index = static_cast<std::size_t>(at);
        EXPECT_EQ(shownText(program, rewind.shownLevel(), rewind), states[index])
            << "state at step " << at;
        hitbox::Timeline shown;
        shown.addStep(at, rewind.getContactEvents());
        EXPECT_EQ(hitbox::timelineCsv(shown.getEvents()), events[index])
            << "contact events of step " << at;
        ++seen.stepsShown;
        for (const hitbox::TimelineEvent& event : shown.getEvents())
        {
            seen.enters += event.kind == hitbox::ContactPhase::Enter;
            seen.stays += event.kind == hitbox::ContactPhase::Stay;
            seen.exits += event.kind == hitbox::ContactPhase::Exit;
        }
        return !testing::Test::HasFailure();
    };
    for (long long step = 1; step <= steps; ++step)
    {
        for (hitbox::Input* each : {&referenceInput, &input})
            if (program.keys)
                program.keys(*each, step - 1);
        for (auto [level, in] :
             {std::pair<hitbox::Level*, hitbox::Input*>{reference.get(), &referenceInput},
              {&rewind, &input}})
        {
            level->handleInput(*in, hitbox::stepSeconds);
            level->update(hitbox::stepSeconds);
            in->update();
        }
        states.push_back(shownText(program, *reference, *reference));
        events.push_back(eventsText(step, reference->getContactEvents()));
        EXPECT_EQ(shownText(program, rewind.shownLevel(), rewind), states.back())
            << "live state at step " << step;
        EXPECT_EQ(eventsText(step, rewind.getContactEvents()), events.back())
            << "live contact events of step " << step;
        if (std::find(pauses.begin(), pauses.end(), step) == pauses.end())
            continue;
        EXPECT_EQ(rewind.oldestStep(), std::max(0LL, step - kept));
        for (long long at = step; at >= rewind.oldestStep(); --at)
            if (!check(at))
                return seen;
        for (long long at = rewind.oldestStep(); at <= step; ++at)
            if (!check(at))
                return seen;
        for (long long at : {rewind.oldestStep() + kept / 3, step - 1, rewind.oldestStep()})
            if (!check(at))
                return seen;
    }
    // What it held (Rewind.h's bytesUsed) and, saved, one snapshot of this scene.
    const std::unique_ptr<hitbox::LevelState> one = live->saveState();
    std::cout << "rewind: " << seen.stepsShown << " steps shown ("
              << (seen.rebuilt ? "rebuilt" : "restored") << "), " << seen.enters << " enters, "
              << seen.stays << " stays, " << seen.exits << " exits; " << rewind.bytesUsed()
              << " bytes held for " << kept << " steps"
              << (one ? ", " + std::to_string(one->bytes()) + " bytes a snapshot" : std::string())
              << std::endl;
    return seen;
}

} // namespace rewindcheck
