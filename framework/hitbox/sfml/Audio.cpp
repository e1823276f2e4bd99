#include "hitbox/sfml/Audio.h"

namespace hitbox
{

bool loadMonoSamples(sf::SoundBuffer& buffer, const std::vector<std::int16_t>& samples,
                     unsigned sampleRate)
{
#if SFML_VERSION_MAJOR >= 3
    return buffer.loadFromSamples(samples.data(), samples.size(), 1, sampleRate,
                                  {sf::SoundChannel::Mono});
#else
    return buffer.loadFromSamples(samples.data(), samples.size(), 1, sampleRate);
#endif
}

void setLooping(sf::SoundStream& stream, bool looping)
{
#if SFML_VERSION_MAJOR >= 3
    stream.setLooping(looping);
#else
    stream.setLoop(looping);
#endif
}

} // namespace hitbox
