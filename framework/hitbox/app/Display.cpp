#include "hitbox/app/Display.h"

#include "hitbox/platform/Platform.h"

namespace hitbox
{

#if defined(_WIN32) || defined(__APPLE__)

DisplayCheck checkDisplay()
{
    return {true, "", nullptr};
}

#else

namespace
{
// Asks the X server itself, the way SFML will: XOpenDisplay(NULL) connects to $DISPLAY.
// libX11 is loaded at run time (SFML's window module loads it anyway), so building Hitbox
// needs no X11 headers. Returns the open connection, or null when nobody answers.
std::shared_ptr<void> connectToXServer()
{
    std::shared_ptr<void> library = platform::loadLibrary("libX11.so.6");
    if (library == nullptr)
        return nullptr; // no libX11: SFML could not open a window either
    using OpenDisplay = void* (*)(const char*);
    using CloseDisplay = int (*)(void*);
    const auto open = reinterpret_cast<OpenDisplay>(platform::findSymbol(library, "XOpenDisplay"));
    const auto close =
        reinterpret_cast<CloseDisplay>(platform::findSymbol(library, "XCloseDisplay"));
    void* display = open != nullptr && close != nullptr ? open(nullptr) : nullptr;
    if (display == nullptr)
        return nullptr;
    // The connection keeps the library loaded until it is closed.
    return std::shared_ptr<void>(display,
                                 [library, close](void* connection) { close(connection); });
}
} // namespace

DisplayCheck checkDisplay()
{
    const std::string x11 = platform::environmentVariable("DISPLAY").value_or("");
    const std::string wayland = platform::environmentVariable("WAYLAND_DISPLAY").value_or("");
    const bool waylandOnly = !wayland.empty();
    if (x11.empty())
        return {false,
                waylandOnly ? "only WAYLAND_DISPLAY is set, and SFML needs X11 (Xwayland)"
                            : "DISPLAY is not set",
                nullptr};
    std::shared_ptr<void> connection = connectToXServer();
    if (connection == nullptr)
        return {false, "no X server answers at DISPLAY=" + x11, nullptr};
    return {true, "", connection};
}

#endif

} // namespace hitbox
