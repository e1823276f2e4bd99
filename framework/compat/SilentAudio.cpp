// Compiled into every 2019-24 course lab (SFML 2, whose sound goes through OpenAL Soft), and
// only there: before main() starts, with no sound device, OpenAL Soft's silent driver and one
// line instead of an error for every sound. The rule lives in Hitbox's platform layer
// (hitbox/platform/SilentAudio.h), shared with Hitbox's own programs (app/App.cpp).
#include "hitbox/platform/SilentAudio.h"

#include <iostream>

namespace
{

bool silenceAudioWithoutDevice()
{
    const auto line = hitbox::platform::silenceAudioWithoutDevice();
    if (line)
        std::cerr << "Hitbox: " << *line << '\n';
    return line.has_value();
}

// Runs before main(), so before the lab makes its first sound.
[[maybe_unused]] const bool silenced = silenceAudioWithoutDevice();

} // namespace
