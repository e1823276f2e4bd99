// Display.h - can a window be opened here? Asked before SFML tries, because SFML aborts the
// whole process (exit 134, uncatchable) when it cannot reach a display.
#pragma once

#include <memory>
#include <string>

namespace hitbox
{

struct DisplayCheck
{
    bool available = false;
    std::string reason; // when not available: why, in a few words, e.g. "DISPLAY is not set"
    // Linux: the check's own connection to the X server, closed when the last copy of this
    // is destroyed. Keep it while the window is open: when its last client leaves, an X
    // server such as Xvfb resets, and SFML connecting during that reset aborts.
    std::shared_ptr<void> connection;
};

// On Linux SFML draws through X11, so a display is available only when the X server named
// by DISPLAY answers: an unset or stale DISPLAY, or only WAYLAND_DISPLAY set (no Xwayland),
// is "no display". Windows and macOS always have one.
[[nodiscard]] DisplayCheck checkDisplay();

} // namespace hitbox
