#include "hitbox/app/Display.h"

#include <cstdlib>

#if !defined(_WIN32) && !defined(__APPLE__)
#include <dlfcn.h>
#endif

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
    void* library = dlopen("libX11.so.6", RTLD_LAZY | RTLD_LOCAL);
    if (library == nullptr)
        return nullptr; // no libX11: SFML could not open a window either
    using OpenDisplay = void* (*)(const char*);
    using CloseDisplay = int (*)(void*);
    const auto open = reinterpret_cast<OpenDisplay>(dlsym(library, "XOpenDisplay"));
    const auto close = reinterpret_cast<CloseDisplay>(dlsym(library, "XCloseDisplay"));
    void* display = open != nullptr && close != nullptr ? open(nullptr) : nullptr;
    if (display == nullptr)
    {
        dlclose(library);
        return nullptr;
    }
    return std::shared_ptr<void>(display,
                                 [library, close](void* connection)
                                 {
                                     close(connection);
                                     dlclose(library);
                                 });
}
} // namespace

DisplayCheck checkDisplay()
{
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const bool waylandOnly = wayland != nullptr && *wayland != '\0';
    if (x11 == nullptr || *x11 == '\0')
        return {false,
                waylandOnly ? "only WAYLAND_DISPLAY is set, and SFML needs X11 (Xwayland)"
                            : "DISPLAY is not set",
                nullptr};
    std::shared_ptr<void> connection = connectToXServer();
    if (connection == nullptr)
        return {false, "no X server answers at DISPLAY=" + std::string(x11), nullptr};
    return {true, "", connection};
}

#endif

} // namespace hitbox
