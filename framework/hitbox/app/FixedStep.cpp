#include "hitbox/app/FixedStep.h"

#include <algorithm>
#include <cmath>

namespace hitbox
{

FixedStep::FixedStep(float stepSeconds, float maxFrameSeconds)
    : stepSeconds(stepSeconds), maxFrameSeconds(std::max(maxFrameSeconds, stepSeconds))
{
}

int FixedStep::advance(float frameSeconds)
{
    if (!(frameSeconds > 0.f)) // also catches NaN
        return 0;
    savedSeconds += std::min<double>(frameSeconds, maxFrameSeconds);
    // A tolerance of 0.01% of a step, so that frames exactly one step long give one step
    // each despite rounding.
    const int steps = static_cast<int>(std::floor(savedSeconds / stepSeconds + 1e-4));
    savedSeconds = std::max(0.0, savedSeconds - steps * stepSeconds);
    return steps;
}

float FixedStep::getStepSeconds() const
{
    return static_cast<float>(stepSeconds);
}

float FixedStep::getLeftoverFraction() const
{
    return static_cast<float>(std::min(1.0, savedSeconds / stepSeconds));
}

} // namespace hitbox
