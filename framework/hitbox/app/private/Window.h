// Window.h - the windowed half of hitbox::App: the window the loop (Loop.h) runs in and where
// the shared keys (Keys.h) act. What it draws is Frame.h; a --screenshot run, with no window,
// ScreenshotRun.h. Only App.cpp calls this.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/Options.h"
#include "hitbox/app/private/RewindStrip.h"

namespace hitbox
{

// Opens a letterboxed, resizable window and runs `level` in it until it is closed.
[[nodiscard]] int runWindow(Level& level, const Options& options, const ProgramInfo& info,
                            RewindTools tools = {});

} // namespace hitbox
