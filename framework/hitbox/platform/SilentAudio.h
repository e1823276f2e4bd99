// SilentAudio.h - no sound device: one line, then silence, instead of an error per sound.
//
// SFML 2 plays sound through OpenAL Soft, which with no sound device (a server, a container,
// CI under Xvfb) prints an error for every sound it cannot play: a course lab wrote 918,000
// lines in 4 s (issue 25, finding 26). Before the first sound, a program calls this once;
// when the machine has no sound device and the user has not chosen an OpenAL driver
// (ALSOFT_DRIVERS), it picks OpenAL Soft's "null" driver (sounds play silently, in time).
// Used by Hitbox's own programs (app/App.cpp) and by the old course labs
// (framework/compat/SilentAudio.cpp). SFML 3 needs none of it (its miniaudio backend says
// once that it found no device), but it does no harm there. Knows no SFML.
#pragma once

#include <optional>
#include <string>

namespace hitbox::platform
{

// The line to print (without the program's name) when it chose the silent driver; nullopt
// when sound is left alone: a device was found, ALSOFT_DRIVERS is already set, or the system
// is not Linux (Windows and macOS always have an audio service for OpenAL to talk to).
[[nodiscard]] std::optional<std::string> silenceAudioWithoutDevice();

} // namespace hitbox::platform
