// Window.h - the windowed half of hitbox::App: the window the loop (Loop.h) runs in, where
// the shared keys (Keys.h) act, the help line and screenshots. Only App.cpp calls these.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/Options.h"
#include "hitbox/app/Rewind.h"
#include "hitbox/app/Timeline.h"

namespace hitbox
{

// What the paused window can rewind (null: nothing) and the events its strip shows.
struct RewindTools
{
    RewindLevel* rewind = nullptr;
    const Timeline* timeline = nullptr;
};

// Opens a letterboxed, resizable window and runs `level` in it until it is closed.
[[nodiscard]] int runWindow(Level& level, const Options& options, const ProgramInfo& info,
                            RewindTools tools = {});

// Simulates options.frames steps (default 0), draws one frame into options.screenshotPath.
[[nodiscard]] int saveScreenshot(Level& level, const Options& options, const ProgramInfo& info);

} // namespace hitbox
