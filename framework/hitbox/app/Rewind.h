// Rewind.h - step back and forward through the last seconds of a run while paused.
//
// A RewindLevel wraps the level the loop runs. Every step it writes down the input, and every
// snapshotSteps steps a copy of the level's state (Level::saveState). Showing an earlier step
// restores the snapshot at or before it and simulates the written-down input up to it: the
// run is deterministic, so that is the step as it was, bit for bit. Rewinding only looks back:
// the next live step first returns to the newest step, so the run goes on exactly as it
// would have (and --record and --timeline see one unbroken run).
//
// Memory is bounded: snapshots older than the kept seconds are dropped, so at most
// keptSteps / snapshotSteps + 2 snapshots and keptSteps + snapshotSteps inputs are held;
// bytesUsed() says what they cost.
#pragma once

#include "hitbox/app/Loop.h"
#include "hitbox/app/Replay.h"
#include "hitbox/app/ReplayLevel.h"

#include <cstddef>
#include <deque>
#include <memory>
#include <utility>

namespace hitbox
{

// How far back the window's Left arrow goes: the last 10 simulated seconds.
constexpr long long rewindSteps = 10 * static_cast<long long>(stepsPerSecond);
// A snapshot every quarter second: going back one step re-simulates at most 29 steps.
constexpr long long rewindSnapshotSteps = 30;

class RewindLevel : public WrappedLevel
{
public:
    RewindLevel(Level& inner, long long keptSteps = rewindSteps,
                long long snapshotSteps = rewindSnapshotSteps);

    void handleInput(const Input& input, float dt) override;
    void update(float dt) override;

    // False when the level cannot be saved (Level::saveState gave nullptr): nothing to go to.
    [[nodiscard]] bool canRewind() const { return !snapshots.empty(); }
    // The earliest step that can be shown, the newest (the live one) and the one shown now.
    [[nodiscard]] long long oldestStep() const;
    [[nodiscard]] long long newestStep() const { return step; }
    [[nodiscard]] long long shownStep() const { return shown; }
    // Shows step `wanted`, clamped to oldestStep()..newestStep(); returns the step shown.
    long long show(long long wanted);
    // The bytes the snapshots and the inputs hold now.
    [[nodiscard]] std::size_t bytesUsed() const;

private:
    void snapshot();

    long long keptSteps;
    long long snapshotSteps;
    std::deque<std::pair<long long, std::unique_ptr<LevelState>>> snapshots; // (step, state)
    std::deque<InputSnapshot> inputs; // inputs[i] is the input of step firstInput + i
    long long firstInput = 0;
    long long shown = 0;
};

} // namespace hitbox
