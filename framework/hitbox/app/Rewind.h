// Rewind.h - step back and forward through the last seconds of a run while paused.
//
// A RewindLevel wraps the level the loop runs and writes down every step's input. Showing an
// earlier step then works one of two ways, and both give the step as it was, bit for bit (the
// run is deterministic):
//   - a level that can save its state (Level::saveState): every snapshotSteps steps a copy of
//     it; showing step t restores the copy at or before t and simulates the written-down input
//     up to t (at most snapshotSteps - 1 steps a key press);
//   - any other level, given a LevelMaker: the level is built again and fed the input from
//     step 0 (RewindReplay.h), so every program can be rewound with no code of its own.
// Rewinding only looks back: the next live step first returns to the newest step, so the run
// goes on exactly as it would have (and --record and --timeline see one unbroken run).
//
// Memory is bounded: snapshots older than the kept seconds are dropped, so at most
// keptSteps / snapshotSteps + 2 snapshots and keptSteps + snapshotSteps inputs are held. A
// level rebuilt instead keeps one input row per step whose input changed (as --record does),
// for the first rebuildSteps steps only; after those, it can no longer be rewound.
// bytesUsed() says what either costs.
#pragma once

#include "hitbox/app/Loop.h"
#include "hitbox/app/Replay.h"
#include "hitbox/app/ReplayLevel.h"
#include "hitbox/app/RewindReplay.h"

#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hitbox
{

// How far back the window's Left arrow goes: the last 10 simulated seconds.
constexpr long long rewindSteps = 10 * static_cast<long long>(stepsPerSecond);
// A snapshot every quarter second: going back one step re-simulates at most 29 steps.
constexpr long long rewindSnapshotSteps = 30;
// A level rebuilt to be shown (RewindReplay.h) is re-simulated from step 0 and needs every
// input row since then, so its rewind stops after the first 10 simulated minutes: at most
// 72,000 rows (about 7 MiB with the mouse moving every step) and about a second of CPU a key
// press in a debug build (docs/debugging.md has the figures).
constexpr long long rewindRebuildSteps = 10 * 60 * static_cast<long long>(stepsPerSecond);

class RewindLevel : public WrappedLevel
{
public:
    RewindLevel(Level& inner, long long keptSteps = rewindSteps,
                long long snapshotSteps = rewindSnapshotSteps);
    // As above; when `inner` cannot save its state, `remake` builds it again for showing an
    // earlier step (RewindReplay.h). It must build the level exactly as `inner` was built.
    RewindLevel(Level& inner, LevelMaker remake, long long keptSteps = rewindSteps,
                long long snapshotSteps = rewindSnapshotSteps,
                long long rebuildSteps = rewindRebuildSteps);

    void handleInput(const Input& input, float dt) override;
    void update(float dt) override;
    // Drawn and described: the step shown (a rebuilt level's, while looking back).
    void render(sf::RenderTarget& target) const override;
    void renderBlended(sf::RenderTarget& target, float leftover) const override;
    void renderDebug(DebugRenderer& debug) const override;
    // (the help line too: many levels show their state in it)
    [[nodiscard]] std::string getHelpText() const override;
    [[nodiscard]] std::string describeState() const override;
    [[nodiscard]] std::vector<PairEvent> getContactEvents() const override;

    // False when the level can neither be saved (Level::saveState gave nullptr) nor rebuilt
    // (no LevelMaker, or the run is past rebuildSteps): nothing to go to.
    [[nodiscard]] bool canRewind() const { return !snapshots.empty() || replayed != nullptr; }
    // True when an earlier step is shown by a rebuilt level (RewindReplay.h).
    [[nodiscard]] bool rebuilds() const { return replayed != nullptr; }
    // The earliest step that can be shown, the newest (the live one) and the one shown now.
    [[nodiscard]] long long oldestStep() const;
    [[nodiscard]] long long newestStep() const { return step; }
    [[nodiscard]] long long shownStep() const { return shown; }
    // Shows step `wanted`, clamped to oldestStep()..newestStep(); returns the step shown.
    long long show(long long wanted);
    // The bytes the snapshots and the inputs hold now.
    [[nodiscard]] std::size_t bytesUsed() const;
    // Steps re-simulated to show earlier steps so far (what looking back has cost).
    [[nodiscard]] long long stepsReplayed() const;

    // The level the shown step is in: the wrapped one, or a rebuilt one while looking back.
    [[nodiscard]] const Level& shownLevel() const;

private:
    void snapshot();

    long long keptSteps;
    long long snapshotSteps;
    long long rebuildSteps = rewindRebuildSteps;
    std::deque<std::pair<long long, std::unique_ptr<LevelState>>> snapshots; // (step, state)
    std::deque<InputSnapshot> inputs; // inputs[i] is the input of step firstInput + i
    long long firstInput = 0;
    long long shown = 0;
    long long resimulated = 0;
    std::unique_ptr<ReplayedRun> replayed; // set when the level is rebuilt, not restored
    const Level* rebuilt = nullptr;        // the rebuilt level shown, while looking back
};

} // namespace hitbox
