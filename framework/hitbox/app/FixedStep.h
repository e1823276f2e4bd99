// FixedStep.h - turn uneven frame times into a whole number of equal simulation steps.
//
// The accumulator pattern ("Fix your timestep"): frame time is saved up and spent in
// steps of exactly `stepSeconds`, so the simulation gives the same result at 30 or 300
// frames per second. After a stall (a dragged window, a breakpoint) at most
// `maxFrameSeconds` of time is simulated: the game slows down for a moment instead of
// running hundreds of steps, and no step is ever longer than `stepSeconds`, so nothing
// jumps through a wall.
#pragma once

namespace hitbox
{

class FixedStep
{
public:
    // Steps of `stepSeconds` (every program passes hitbox::stepSeconds, App.h).
    explicit FixedStep(float stepSeconds, float maxFrameSeconds = 0.25f);

    // Add one frame's time; returns how many steps to simulate now (0 or more).
    // Negative or NaN frame times count as 0.
    int advance(float frameSeconds);

    float getStepSeconds() const;
    // Time saved up but not yet simulated, as a fraction of a step (0 to 1).
    float getLeftoverFraction() const;

private:
    double stepSeconds;
    double maxFrameSeconds;
    double savedSeconds = 0.0;
};

} // namespace hitbox
