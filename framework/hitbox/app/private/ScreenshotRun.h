// ScreenshotRun.h - pictures of a level: a --screenshot run (simulate, then draw one frame
// into a picture file, with no window), and F12's picture of the window.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/Options.h"

#include <SFML/Graphics/RenderWindow.hpp>

namespace hitbox
{

// Simulates options.frames steps (default 0), draws one frame into options.screenshotPath.
// A name that cannot take a picture is refused (exit 1) before the simulation starts.
[[nodiscard]] int saveScreenshot(Level& level, const Options& options, const ProgramInfo& info);

// F12: the window as it is now, saved as screenshot-STAMP.png in the working folder (a free
// name: Screenshot.h); says "Saved NAME" or, on stderr, why not. The window goes on either way.
void saveWindowPicture(const sf::RenderWindow& window);

} // namespace hitbox
