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
//     --frames N          simulate N fixed steps (headless default 600, i.e. 5 seconds);
//                         in a window: close it after N steps
//     --seconds S         the same, in simulated seconds (0.5 is 60 steps)
//     --screenshot F.png  simulate --frames steps (default 0), draw one frame into F.png
//     --debug             start with the debug boxes shown
//     --seed N            seed for anything random (default 1)
//     --help, -h          print the usage page (Options.h, usagePage)
// and the same keys in the window:
//     F1 debug boxes   P pause   N one step while paused   F12 screenshot   Esc quit
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/Options.h"

#include <SFML/Graphics/Rect.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hitbox
{

// Simulation steps per second. Every program and every test uses the same step.
constexpr float stepsPerSecond = 120.f;
constexpr float stepSeconds = 1.f / stepsPerSecond;

using LevelFactory = std::function<std::unique_ptr<Level>(const Options&)>;

// Runs the program; returns main()'s exit code (0 fine, 1 error, 2 bad usage / no display,
// 130 stopped by Ctrl-C while simulating without a window). --help prints usagePage(), 0.
[[nodiscard]] int run(int argc, char* argv[], const ProgramInfo& info,
                      const LevelFactory& makeLevel);

// Runs `frames` fixed steps with no input and no window. Used by --headless and tests.
void simulate(Level& level, long long frames);

// The longest side of a --screenshot picture: a world larger than this (or than the
// graphics driver's largest texture) is drawn shrunk to fit, whole.
constexpr unsigned maxPictureSide = 4096;

// `size` in whole pixels, shrunk (never grown, never stretched) to fit inside `limit`;
// at least 1 x 1. A zero, negative or NaN side counts as 1 pixel.
[[nodiscard]] sf::Vector2u fitInside(sf::Vector2f size, sf::Vector2u limit);

// The part of a window, as fractions of its size (a view's viewport), that shows a world
// of `worldSize` as large as possible without stretching: bars fill the rest (letterbox).
[[nodiscard]] sf::FloatRect letterboxViewport(sf::Vector2u windowSize, sf::Vector2f worldSize);

} // namespace hitbox
