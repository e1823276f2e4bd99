#include "hitbox/app/Loop.h"

#include "hitbox/app/FixedStep.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Level.h"

namespace hitbox
{

void runLoop(Level& level, LoopHost& host)
{
    FixedStep lag(stepSeconds);
    Input input;
    while (host.isRunning())
    {
        host.processInput(input);
        const int steps = host.stepsToRun(lag.advance(host.secondsSinceLastFrame()));
        for (int step = 0; step < steps; ++step)
        {
            level.handleInput(input, stepSeconds);
            level.update(stepSeconds);
            input.update(); // a key press is seen by exactly one step
        }
        host.render(level, lag.getLeftoverFraction());
    }
}

} // namespace hitbox
