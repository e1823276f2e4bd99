// App.h - run a Level in a window, headless, or for one screenshot.
//
// Every Hitbox program's main() is one call:
//     int main(int argc, char* argv[])
//     {
//         return hitbox::run(argc, argv, {"Lab 2 - Bouncing balls"},
//                            [](const hitbox::Options&) { return std::make_unique<BallsLevel>();
//                            });
//     }
// and so every program understands the same command line:
//     --headless          no window: simulate only, then print one line of final state
//     --frames N          simulate N fixed steps (headless: headlessDefaultSteps, Options.h);
//                         in a window: close it after N steps
//     --seconds S         the same, in simulated seconds (0.5 is 60 steps)
//     --screenshot F.png  simulate --frames steps (default 0), draw one frame into F.png
//     --debug             start with the debug boxes shown
//     --seed N            seed for anything random (default 1)
//     --record FILE       write the seed, options and each step's input (Replay.h)
//     --replay FILE       run a recording again, exactly; --pause-at-step N pauses there
//     --timeline F.csv    write every contact event (Timeline.h)
//     --help, -h          print the usage page (Options.h, usagePage)
// and the same keys in the window:
//     F1 debug boxes   P pause   N one step while paused   F12 screenshot   Esc quit
// and, paused, Left/Right (or a click on the strip) to step through the last 10 s (Rewind.h).
#pragma once

#include "hitbox/app/Letterbox.h"
#include "hitbox/app/Level.h"
#include "hitbox/app/Loop.h"
#include "hitbox/app/Options.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hitbox
{

using LevelFactory = std::function<std::unique_ptr<Level>(const Options&)>;

// Runs the program; returns main()'s exit code (0 fine, 1 error, 2 bad usage / no display,
// 130 stopped by Ctrl-C while simulating without a window). --help prints usagePage(), 0.
[[nodiscard]] int run(int argc, char* argv[], const ProgramInfo& info,
                      const LevelFactory& makeLevel);

// Runs `frames` fixed steps with no input and no window. Used by --headless and tests.
void simulate(Level& level, long long frames);

} // namespace hitbox
