// Framework/AudioManager.h - the course's sound effects and music, played by name:
//     audio->addSound("sfx/jump.ogg", "jump");      // once, when the level is made
//     audio->playSoundbyName("jump");                // whenever it should play
//     audio->addMusic("sfx/theme.ogg", "theme");
//     audio->playMusicbyName("theme");
//
// Harmless without a sound device: loading and playing work as usual and nothing is heard
// (OpenAL may print that it found no device; ALSOFT_DRIVERS=null keeps it quiet). A name
// that was never added plays nothing; a file that does not load gets one line from SFML.
#pragma once

#include "../CourseMusic.h"
#include "Framework/MusicObject.h"
#include "Framework/SoundObject.h"

#include <SFML/Audio.hpp>
#include <deque>
#include <string>

class AudioManager
{
public:
    AudioManager();
    ~AudioManager();

    void addSound(std::string filename, std::string lname);
    // Starts the named sound from its beginning (again, if it is already playing).
    void playSoundbyName(std::string lname);
    void stopAllSounds();
    // The named sound, to change its volume or pitch; nullptr for a name never added.
    sf::Sound* getSound(std::string lname);

    void addMusic(std::string filename, std::string lname);
    // Stops the music playing now and streams the named one, looping.
    void playMusicbyName(std::string lname);
    void stopAllMusic();
    sf::Music* getMusic();

private:
    // std::deque: adding a sound never moves the others, so getSound's pointers stay valid.
    std::deque<SoundObject> sounds;
    CourseMusic music; // shared with the 2025-26 AudioManager
};
