// RewindReplay.h - how the rewind shows an earlier step of a level that cannot save its state
// (Level::saveState gives nullptr): it builds the level again, exactly as the program first
// built it, and feeds it the written-down input of every step from the start, as --replay does.
// The run is deterministic (Replay.h), so that is the step as it was, bit for bit; no level
// needs code of its own for it (a World's contacts, a student's own fields: all re-made).
//
// The live level is never touched: the rebuilt one is only looked at, then dropped.
// Cost: going forward from the step shown is one step per step; going back re-simulates from
// step 0 (docs/debugging.md states what that costs, measured). Memory: the input rows (one per
// step whose input changed, as --record keeps) and, while looking back, one more level.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/Replay.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <utility>

namespace hitbox
{

// Builds the level anew, as the program built the one that runs (same seed and options).
using LevelMaker = std::function<std::unique_ptr<Level>()>;

class ReplayedRun
{
public:
    explicit ReplayedRun(LevelMaker remake) : remake(std::move(remake)) {}

    // Writes down the input of the next live step.
    void addStep(const InputSnapshot& input) { inputs.addStep(input); }
    // The level as it was after `step` steps (0 to the steps written down): the one shown
    // last, moved on, when it is not past `step`; else one built anew and re-simulated.
    [[nodiscard]] const Level& levelAt(long long step);
    // Drops the rebuilt level (back to the live one).
    void forget() { shown.reset(); }
    // The bytes the input rows hold (the rebuilt level, while there is one, is not counted).
    [[nodiscard]] std::size_t bytesUsed() const;
    // How many steps showing has re-simulated so far (what going back costs, for tests).
    [[nodiscard]] long long stepsReplayed() const { return replayed; }

private:
    LevelMaker remake;
    Recording inputs;
    std::unique_ptr<Level> shown;
    long long shownStep = 0;
    long long replayed = 0;
};

} // namespace hitbox
