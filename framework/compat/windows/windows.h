// windows.h - a stand-in, on Linux and macOS, for the few Win32 calls course labs make.
// Only a course-lab build puts this folder on the include path, and only off Windows (where
// the real <windows.h> is used); the build says so in one line when a lab includes it.
//
// What labs use it for: sizing the window to the desktop, and pausing.
//     GetSystemMetrics(SM_CXSCREEN), GetSystemMetrics(SM_CYSCREEN): the desktop's width and
//         height in pixels, from SFML's desktop video mode (the primary screen, as Win32's);
//         any other index gives 0, as Win32 does for an index it does not know.
//     Sleep(milliseconds): pauses the calling thread.
// Anything else from Win32 is not here: the compiler names it, and the lab needs changing.
#pragma once

#include <SFML/Config.hpp>
#include <SFML/Window/VideoMode.hpp>

#include <chrono>
#include <thread>

using DWORD = unsigned long;

// Win32's values for these indices (winuser.h).
constexpr int SM_CXSCREEN = 0;
constexpr int SM_CYSCREEN = 1;

inline int GetSystemMetrics(int index)
{
    const sf::VideoMode desktop = sf::VideoMode::getDesktopMode();
#if SFML_VERSION_MAJOR >= 3
    const unsigned width = desktop.size.x;
    const unsigned height = desktop.size.y;
#else
    const unsigned width = desktop.width;
    const unsigned height = desktop.height;
#endif
    if (index == SM_CXSCREEN)
        return static_cast<int>(width);
    if (index == SM_CYSCREEN)
        return static_cast<int>(height);
    return 0;
}

inline void Sleep(DWORD milliseconds)
{
    std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
}
