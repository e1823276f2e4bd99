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

#include <string>
#include <vector>

class StackLevel : public hitbox::Level
{
public:
    static constexpr int crateCount = 10;       // crates in each stack
    static constexpr float crateSize = 50.f;    // pixels
    static constexpr float floorY = 640.f;      // the floor line, pixels from the top
    static constexpr int shakyPasses = 1;       // the left stack's passes a step
    static constexpr int startPasses = 8;       // the right stack's, at the start
    static constexpr int maxPasses = 30;        // Up stops here
    static constexpr int stepsPerReadout = 120; // the readout's window: one second

    StackLevel();

    void handleInput(const Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // For the grading tests and experiments: the largest one-step move of a crate of stack
    // `stack` (0 left, 1 right) over the last full readout window.
    float getShake(int stack) const;
    int getPasses(int stack) const;

private:
    void restack();

    std::vector<Crate> stacks[2];
    int passes[2] = {shakyPasses, startPasses};
    float largestMoveNow[2] = {};   // in the window being measured
    float largestMoveShown[2] = {}; // in the last full window
    int stepsInWindow = 0;
};
