#include "hitbox/app/Loop.h"

#include "hitbox/app/App.h"
#include "hitbox/app/FixedStep.h"
#include "hitbox/app/Input.h"

namespace hitbox
{

void runLoop(Level& level, LoopHost& host)
{
    FixedStep fixedStep(stepSeconds);
    Input input;
    while (host.isRunning())
    {
        const float frameSeconds = host.processInput(input);
        const int steps = host.stepsToRun(fixedStep.advance(frameSeconds));
        for (int step = 0; step < steps; ++step)
        {
            level.handleInput(input, stepSeconds);
            level.update(stepSeconds);
            input.update(); // a key press is seen by exactly one step
        }
        host.render(level);
    }
}

} // namespace hitbox
