// Framework/SoundObject.h - one named sound effect of the course's AudioManager.
//
// The sound plays from a buffer this object owns, so a SoundObject cannot be copied (the
// copy's sound would play the first one's buffer after it was gone).
#pragma once

#include <SFML/Audio.hpp>
#include <string>

class SoundObject
{
public:
    SoundObject();
    ~SoundObject();
    SoundObject(const SoundObject&) = delete;
    SoundObject& operator=(const SoundObject&) = delete;

    // Loads the file (WAV, OGG, FLAC) and names the sound. A file that does not load leaves
    // a sound that plays nothing (SFML prints one line saying which file).
    void loadSound(std::string filename, std::string lname);

    sf::Sound sound;
    std::string name;

private:
    sf::SoundBuffer buffer;
};
