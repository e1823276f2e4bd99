// Sounds.h - the game's sound effects, synthesized at start-up (no sound files to ship).
//
// The simulation only writes down GameEvents; this layer turns them into sounds. It is
// created only by a program with a window (main.cpp): headless runs and tests never make
// one, because SFML opens the audio device as soon as a sound buffer exists. With no audio
// device the sounds simply play silently.
#pragma once

#include "GameEvents.h"

#include <SFML/Audio/Sound.hpp>
#include <SFML/Audio/SoundBuffer.hpp>
#include <cstdint>
#include <vector>

// A square-wave beep like the arcade original's, as 16-bit mono samples. It fades out over
// its last few milliseconds so it ends without a click. Needs no audio device (testable).
std::vector<std::int16_t> synthesizeBeep(float frequencyHz, float seconds, unsigned sampleRate);

class Sounds
{
public:
    Sounds();
    Sounds(const Sounds&) = delete; // sf::Sound points at the buffers: never copy
    Sounds& operator=(const Sounds&) = delete;

    // Plays one sound per kind of event that happened this step.
    void play(const std::vector<GameEvent>& events);

private:
    static constexpr unsigned sampleRate = 44100;
    sf::SoundBuffer paddleBuffer;
    sf::SoundBuffer wallBuffer;
    sf::SoundBuffer pointBuffer;
    sf::Sound paddleSound; // made after the buffers it plays
    sf::Sound wallSound;
    sf::Sound pointSound;
};
