// Loop.h - the game loop: every Hitbox program, with a window or --headless, runs this.
//
// Frame time is saved up and spent in steps of exactly stepSeconds, so the rules give the
// same result at any frame rate; drawing happens once per frame, however many steps ran,
// with the time left over as a fraction of a step (Nystrom, Game Programming Patterns,
// "Game Loop": "Play catch up" and "Stuck in the middle").
#pragma once

namespace hitbox
{
class Input;
class Level;

// Simulation steps per second. Every program and every test uses the same step.
constexpr float stepsPerSecond = 120.f;
constexpr float stepSeconds = 1.f / stepsPerSecond;

// Where the loop runs: a window (private/Window.cpp) or nothing at all (--headless, tests).
class LoopHost
{
public:
    virtual ~LoopHost() = default;

    // False ends the loop (the window was closed, or the headless frames are done).
    [[nodiscard]] virtual bool isRunning() const = 0;
    // Seconds of real time since the last call (headless: exactly one step).
    [[nodiscard]] virtual float secondsSinceLastFrame() = 0;
    // Reads this frame's events into `input`.
    virtual void processInput(Input& input) = 0;
    // How many of the `due` steps to run: `due`, or fewer while paused.
    [[nodiscard]] virtual int stepsToRun(int due) = 0;
    // Draws the level once, `leftover` (0 to 1) of a step after its last step.
    virtual void render(const Level& level, float leftover) = 0;
};

// Runs `level` in `host` until the host stops: input, fixed steps, render, every frame.
void runLoop(Level& level, LoopHost& host);

} // namespace hitbox
