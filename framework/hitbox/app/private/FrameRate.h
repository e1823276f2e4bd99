// FrameRate.h - how fast the window draws: the help line's frames per second, and after a
// --frames run the whole run's, for scripts to read.
#pragma once

#include "hitbox/app/Options.h"

#include <SFML/System/Clock.hpp>

namespace hitbox
{

class FrameRate
{
public:
    // One frame drawn. Returns the frames per second over the last half second (0 until the
    // first half second has passed).
    int countFrame();
    // After a --frames run: "TITLE: drew N frames in S s: F frames per second" (the same
    // count as the help line's, which a long debug legend can push out of the window).
    // Nothing for a window the user closes (options.frames < 0) or a run of no time.
    void report(const Options& options, const ProgramInfo& info) const;

private:
    sf::Clock halfSecond;
    sf::Clock run;
    int framesCounted = 0;
    long long framesDrawn = 0;
    int perSecond = 0;
};

} // namespace hitbox
