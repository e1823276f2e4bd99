#include "Sounds.h"

#include <algorithm>
#include <cmath>

std::vector<sf::Int16> synthesizeBeep(float frequencyHz, float seconds, unsigned sampleRate)
{
    const std::size_t count = static_cast<std::size_t>(std::max(0.f, seconds) * sampleRate);
    const std::size_t fadeCount = std::min<std::size_t>(count, sampleRate / 200); // 5 ms
    const float loudness = 0.25f * 32767.f; // a quarter of full scale: not harsh
    std::vector<sf::Int16> samples(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        const float cycles = frequencyHz * static_cast<float>(i) / static_cast<float>(sampleRate);
        const float square = std::fmod(cycles, 1.f) < 0.5f ? 1.f : -1.f;
        const std::size_t fromEnd = count - i;
        const float fade =
            fromEnd < fadeCount ? static_cast<float>(fromEnd) / static_cast<float>(fadeCount) : 1.f;
        samples[i] = static_cast<sf::Int16>(square * loudness * fade);
    }
    return samples;
}

namespace
{
void loadBeep(sf::SoundBuffer& buffer, float frequencyHz, float seconds, unsigned sampleRate)
{
    const std::vector<sf::Int16> samples = synthesizeBeep(frequencyHz, seconds, sampleRate);
    // loadFromSamples fails only if SFML cannot make the buffer; then that sound is silent.
    buffer.loadFromSamples(samples.data(), samples.size(), 1, sampleRate);
}
} // namespace

Sounds::Sounds()
{
    // Pitches close to the 1972 arcade game: a high blip for the paddle, a low one for the
    // walls, and a longer tone for a point.
    loadBeep(paddleBuffer, 460.f, 0.05f, sampleRate);
    loadBeep(wallBuffer, 230.f, 0.04f, sampleRate);
    loadBeep(pointBuffer, 490.f, 0.30f, sampleRate);
    paddleSound.setBuffer(paddleBuffer);
    wallSound.setBuffer(wallBuffer);
    pointSound.setBuffer(pointBuffer);
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
