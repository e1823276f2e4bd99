// FixedStep.h - turn uneven frame times into a whole number of equal simulation steps
// (the accumulator of Glenn Fiedler's "Fix Your Timestep!", Gaffer On Games, and of Nystrom,
// Game Programming Patterns, "Game Loop"): the same result at 30 or 300 frames a second.
#pragma once

namespace hitbox
{

class FixedStep
{
public:
    // Steps of `stepSeconds` (every program passes hitbox::stepSeconds, Loop.h). A frame
    // counts for at most `maxFrameSeconds` (never less than one step): after a stall the
    // game slows down for a moment instead of running hundreds of steps at once.
    explicit FixedStep(float stepSeconds, float maxFrameSeconds = 0.25f);

    // Adds one frame's time; returns how many steps to simulate now (0 or more). Negative
    // or NaN frame times count as 0.
    [[nodiscard]] int advance(float frameSeconds);

    // The step length given to the constructor, in seconds.
    [[nodiscard]] float getStepSeconds() const;
    // Time saved up but not yet simulated, as a fraction of a step (0 to 1).
    [[nodiscard]] float getLeftoverFraction() const;

private:
    double stepSeconds;
    double maxFrameSeconds;
    double savedSeconds = 0.0;
};

} // namespace hitbox
