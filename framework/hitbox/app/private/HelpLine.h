// HelpLine.h - the text of the line along the bottom of every window.
#pragma once

#include "hitbox/app/Level.h"

#include <string>

namespace hitbox
{

// The level's own text (Level::getHelpText: its keys and score), then the shared keys, then the
// frame rate when `framesPerSecond` > 0. With `showDebug`, the debug cues' legend comes first.
// A window too narrow for the line cuts its end: the shared keys, the same in every program.
[[nodiscard]] std::string helpLine(const Level& level, bool showDebug, int framesPerSecond);

} // namespace hitbox
