#include "Sounds.h"

#include "hitbox/sfml/Audio.h"

#include <algorithm>
#include <cmath>

std::vector<std::int16_t> synthesizeBeep(float frequencyHz, float seconds, unsigned sampleRate)
{
    const std::size_t count = static_cast<std::size_t>(std::max(0.f, seconds) * sampleRate);
    const std::size_t fadeCount = std::min<std::size_t>(count, sampleRate / 200); // 5 ms
    const float loudness = 0.25f * 32767.f; // a quarter of full scale: not harsh
    std::vector<std::int16_t> samples(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        const float cycles = frequencyHz * static_cast<float>(i) / static_cast<float>(sampleRate);
        const float square = std::fmod(cycles, 1.f) < 0.5f ? 1.f : -1.f;
        const std::size_t fromEnd = count - i;
        const float fade =
            fromEnd < fadeCount ? static_cast<float>(fromEnd) / static_cast<float>(fadeCount) : 1.f;
        samples[i] = static_cast<std::int16_t>(square * loudness * fade);
    }
    return samples;
}

namespace
{
sf::SoundBuffer makeBeep(float frequencyHz, float seconds, unsigned sampleRate)
{
    sf::SoundBuffer buffer;
    // Fails only if SFML cannot make the buffer; then that sound is silent.
    if (!hitbox::loadMonoSamples(buffer, synthesizeBeep(frequencyHz, seconds, sampleRate),
                                 sampleRate))
        return sf::SoundBuffer();
    return buffer;
}
} // namespace

// Pitches close to the 1972 arcade game: a high blip for the paddle, a low one for the
// walls, and a longer tone for a point.
Sounds::Sounds()
    : paddleBuffer(makeBeep(460.f, 0.05f, sampleRate)),
      wallBuffer(makeBeep(230.f, 0.04f, sampleRate)),
      pointBuffer(makeBeep(490.f, 0.30f, sampleRate)), paddleSound(paddleBuffer),
      wallSound(wallBuffer), pointSound(pointBuffer)
{
}

void Sounds::play(const std::vector<GameEvent>& events)
{
    const auto happened = [&](GameEvent kind)
    { return std::find(events.begin(), events.end(), kind) != events.end(); };
    if (happened(GameEvent::PaddleHit))
        paddleSound.play();
    if (happened(GameEvent::WallHit))
        wallSound.play();
    if (happened(GameEvent::Point) || happened(GameEvent::MatchWon))
        pointSound.play();
}
