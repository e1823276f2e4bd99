// Audio.h - sound calls whose form differs between SFML 2 and SFML 3.
#pragma once

#include <SFML/Audio/SoundBuffer.hpp>
#include <SFML/Audio/SoundStream.hpp>

#include <cstdint>
#include <vector>

namespace hitbox
{

// Fills `buffer` with 16-bit mono `samples` played at `sampleRate` per second; false when
// SFML refuses them (e.g. no samples). SFML 3 also needs the channel layout (mono).
[[nodiscard]] bool loadMonoSamples(sf::SoundBuffer& buffer,
                                   const std::vector<std::int16_t>& samples, unsigned sampleRate);

// Makes `stream` (music) start again from its beginning when it ends, or not (SFML 2:
// setLoop, SFML 3: setLooping).
void setLooping(sf::SoundStream& stream, bool looping);

} // namespace hitbox
