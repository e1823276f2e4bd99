#include "hitbox/app/private/FrameRate.h"

#include <SFML/System/Time.hpp>

#include <iostream>

namespace hitbox
{

int FrameRate::countFrame()
{
    ++framesCounted;
    ++framesDrawn;
    if (halfSecond.getElapsedTime().asSeconds() >= 0.5f)
    {
        perSecond = static_cast<int>(framesCounted / halfSecond.restart().asSeconds() + 0.5f);
        framesCounted = 0;
    }
    return perSecond;
}

void FrameRate::report(const Options& options, const ProgramInfo& info) const
{
    const float seconds = run.getElapsedTime().asSeconds();
    if (options.frames < 0 || seconds <= 0.f)
        return;
    std::cout << info.title << ": drew " << framesDrawn << " frames in " << seconds
              << " s: " << static_cast<float>(framesDrawn) / seconds << " frames per second"
              << std::endl;
}

} // namespace hitbox
