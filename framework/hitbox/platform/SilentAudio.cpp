#include "hitbox/platform/SilentAudio.h"

#include "hitbox/platform/Platform.h"

#include <filesystem>
#include <system_error>

namespace hitbox::platform
{
#if defined(__linux__) // the check reads Linux's devices and sound-server sockets
namespace
{

// A sound card the kernel knows (ALSA's /dev/snd/pcm*), or a sound server's socket
// (PulseAudio, PipeWire) that OpenAL Soft can reach.
bool soundDeviceFound()
{
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator("/dev/snd", error))
        if (entry.path().filename().string().rfind("pcm", 0) == 0)
            return true;
    if (environmentVariable("PULSE_SERVER"))
        return true;
    if (const auto runtime = environmentVariable("XDG_RUNTIME_DIR"))
    {
        const std::filesystem::path folder(*runtime);
        return std::filesystem::exists(folder / "pulse" / "native", error) ||
               std::filesystem::exists(folder / "pipewire-0", error);
    }
    return false;
}

} // namespace
#endif

std::optional<std::string> silenceAudioWithoutDevice()
{
#if defined(__linux__)
    if (environmentVariable("ALSOFT_DRIVERS") || soundDeviceFound())
        return std::nullopt;
    if (!setEnvironmentVariable("ALSOFT_DRIVERS", "null"))
        return std::nullopt;
    return "no sound device found; sounds play silently";
#else
    return std::nullopt;
#endif
}

} // namespace hitbox::platform
