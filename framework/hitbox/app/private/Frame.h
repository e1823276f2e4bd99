// Frame.h - one picture of a level: the same in the window and in a --screenshot file.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/private/RewindStrip.h"

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

namespace hitbox
{

// What the frame shows besides the level.
struct FrameSettings
{
    bool showDebug = false;  // F1: debug shapes, the debug panel, the legend on the help line
    bool paused = false;     // the paused title, and the rewind strip when it can rewind
    int framesPerSecond = 0; // on the help line when > 0
    RewindTools rewind;      // while paused: the strip and Left/Right
};

// The scene (`leftover` of a step after the last one, Loop.h), then the debug shapes and
// panel, the help line, and, paused, the rewind strip and the paused title.
void drawFrame(sf::RenderTarget& target, const Level& level, const sf::Font& font,
               const FrameSettings& settings, float leftover);

} // namespace hitbox
