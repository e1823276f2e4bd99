// HelpLine.h - the text of the line along the bottom of every window.
#pragma once

#include "hitbox/app/Level.h"

#include <string>

namespace hitbox
{

// The shared keys, then the level's own (Level::getHelpText), then the frame rate when
// `framesPerSecond` > 0. With `showDebug`, the debug cues' legend comes first, where a narrow
// window never cuts it off.
[[nodiscard]] std::string helpLine(const Level& level, bool showDebug, int framesPerSecond);

} // namespace hitbox
