// Compiled into every 2019-24 course lab (SFML 2, whose sound goes through OpenAL Soft), and
// only there: with no sound device, OpenAL Soft prints an error for every sound it cannot
// play (a lab wrote 918,000 lines in 4 s). Before main() starts, when the machine has no
// sound device and the user has not chosen an OpenAL driver, this picks OpenAL Soft's
// "null" driver (sounds play silently, in time) and says so in one line.
//
// Linux only: Windows and macOS always have an audio service for OpenAL to talk to. The
// environment is read and set through Hitbox's platform file. SFML 3 labs need nothing: its
// miniaudio backend says once that it found no device.
#if defined(__linux__)

#include "hitbox/platform/Platform.h"

#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

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
    if (hitbox::platform::environmentVariable("PULSE_SERVER"))
        return true;
    if (const auto runtime = hitbox::platform::environmentVariable("XDG_RUNTIME_DIR"))
    {
        const std::filesystem::path folder(*runtime);
        return std::filesystem::exists(folder / "pulse" / "native", error) ||
               std::filesystem::exists(folder / "pipewire-0", error);
    }
    return false;
}

bool silenceAudioWithoutDevice()
{
    if (hitbox::platform::environmentVariable("ALSOFT_DRIVERS") || soundDeviceFound())
        return false;
    hitbox::platform::setEnvironmentVariable("ALSOFT_DRIVERS", "null");
    std::cerr << "Hitbox: no sound device found; sounds play silently\n";
    return true;
}

// Runs before main(), so before the lab makes its first sound.
[[maybe_unused]] const bool silenced = silenceAudioWithoutDevice();

} // namespace

#endif
