// StackLevel.h - two stacks of crates side by side, resolved with different pass counts.
//
// The left stack gets one pass of "find the contacts, push them apart" a step: it sinks into
// itself and shakes. The right one gets `passes` passes (Up/Down change it): from two it
// stops shaking, and with more it sinks less (about 3 pixels of overlap with 4 passes, 1 with
// 8). The readout shows, per stack, the largest distance a crate moved in one step over the
// last second: a resting stack says 0.00.
#pragma once

#include "Stack.h"

#include "hitbox/app/Level.h"
#include "hitbox/app/Loop.h"
#include "hitbox/debug/DebugRenderer.h"

#include <memory>
#include <string>
#include <vector>

// What the debug view shows for each crate: Overlapping when it reaches (or is reached) deeper
// than StackLevel::restingSlop, Touching (resting) when it touches something or reaches at most
// that far, else Free. Plain data, so the tests check it without a window.
std::vector<hitbox::DebugState> crateStates(const std::vector<Crate>& crates, float floorY);

class StackLevel : public hitbox::Level
{
public:
    static constexpr int crateCount = 10;    // crates in each stack
    static constexpr float crateSize = 50.f; // pixels
    static constexpr float floorY = 640.f;   // the floor line, pixels from the top
    static constexpr int shakyPasses = 1;    // the left stack's passes a step
    static constexpr int startPasses = 8;    // the right stack's, at the start
    static constexpr int maxPasses = 30;     // Up stops here
    static constexpr int stepsPerReadout = static_cast<int>(hitbox::stepsPerSecond); // one second
    // The debug view's slop, pixels: a crate reaching at most this far into what holds it up
    // is drawn resting (the "touching" style), not overlapping. Every step gravity pulls a
    // resting crate in a little and the passes take nearly all of it out again, so a right
    // answer rests about 0.9 px deep with startPasses (8): drawn resting. The 1-pass stack,
    // tens of pixels deep, is drawn overlapping.
    static constexpr float restingSlop = 1.f;

    StackLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;
    // The window's rewind (hitbox::RewindLevel): a copy of the whole level, which is all
    // values, so a field added to it is rewound too. Without it the rewind re-simulates from
    // the start, and a step of this lab is slow enough for that to show.
    std::unique_ptr<hitbox::LevelState> saveState() const override;
    void restoreState(const hitbox::LevelState& state) override;

    // For the grading tests and experiments: the largest one-step move of a crate of stack
    // `stack` (0 left, 1 right) over the last full readout window.
    float getShake(int stack) const;
    int getPasses(int stack) const;
    // The crates of stack `stack` (0 left, 1 right), as they are now.
    const std::vector<Crate>& getCrates(int stack) const;

private:
    void restack();

    std::vector<Crate> stacks[2];
    int passes[2] = {shakyPasses, startPasses};
    float largestMoveNow[2] = {};   // in the window being measured
    float largestMoveShown[2] = {}; // in the last full window
    int stepsInWindow = 0;
};
