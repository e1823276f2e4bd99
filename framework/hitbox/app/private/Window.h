// Window.h - the windowed half of hitbox::App: the window the loop (Loop.h) runs in, where
// the shared keys (Keys.h) act, the help line and screenshots. Only App.cpp calls these.
#pragma once

#include "hitbox/app/App.h"

namespace hitbox
{

// Opens a letterboxed, resizable window and runs `level` in it until it is closed.
[[nodiscard]] int runWindow(Level& level, const Options& options, const ProgramInfo& info);

// Simulates options.frames steps (default 0), draws one frame into options.screenshotPath.
[[nodiscard]] int saveScreenshot(Level& level, const Options& options, const ProgramInfo& info);

} // namespace hitbox
