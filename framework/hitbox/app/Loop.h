// Loop.h - the game loop: every Hitbox program, with a window or --headless, runs this.
//
// Frame time is saved up and spent in steps of exactly stepSeconds, so the rules give the
// same result at any frame rate; drawing happens once per frame, however many steps ran
// (Nystrom, Game Programming Patterns, "Game Loop": "Play catch up").
#pragma once

class Input;

namespace hitbox
{
class Level;

// Where the loop runs: a window (private/Window.cpp) or nothing at all (--headless, tests).
class LoopHost
{
public:
    virtual ~LoopHost() = default;

    // False ends the loop (the window was closed, or the headless frames are done).
    [[nodiscard]] virtual bool isRunning() const = 0;
    // Reads this frame's events into `input`; returns the seconds since the last frame.
    [[nodiscard]] virtual float processInput(Input& input) = 0;
    // How many of the `due` steps to run: `due`, or fewer while paused.
    [[nodiscard]] virtual int stepsToRun(int due) = 0;
    // Draws the level once.
    virtual void render(const Level& level) = 0;
};

// Runs `level` in `host` until the host stops: input, fixed steps, render, every frame.
void runLoop(Level& level, LoopHost& host);

} // namespace hitbox
