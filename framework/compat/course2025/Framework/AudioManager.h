// Framework/AudioManager.h (2025-26 course framework) - sound effects and music played by
// name, as the older framework's AudioManager on SFML 3:
//     m_audio.addSound("sfx/jump.ogg", "jump");   // once, when the level is made
//     m_audio.playSoundbyName("jump");            // whenever it should play
//     m_audio.addMusic("sfx/theme.ogg", "theme");
//     m_audio.playMusicbyName("theme");
//
// Harmless without a sound device: loading and playing work and nothing is heard (SFML 3
// prints one line saying it found none). A name never added plays nothing; a file that does
// not load gets one line from SFML and plays nothing.
#pragma once

#include "../../CourseMusic.h"

#include <SFML/Audio.hpp>

#include <deque>
#include <optional>
#include <string>

class AudioManager
{
public:
    AudioManager() = default;
    ~AudioManager();
    AudioManager(const AudioManager&) = delete; // the sounds point into the manager
    AudioManager& operator=(const AudioManager&) = delete;

    void addSound(const std::string& filename, const std::string& name);
    // Starts the named sound from its beginning (again, if it is already playing).
    void playSoundbyName(const std::string& name);
    void stopAllSounds();
    // The named sound, to change its volume or pitch; nullptr for a name never added or a
    // file that did not load.
    sf::Sound* getSound(const std::string& name);

    void addMusic(const std::string& filename, const std::string& name);
    // Stops the music playing now and streams the named one, looping.
    void playMusicbyName(const std::string& name);
    void stopAllMusic();
    sf::Music& getMusic();

private:
    struct NamedSound
    {
        std::string name;
        sf::SoundBuffer buffer;
        std::optional<sf::Sound> sound; // SFML 3: a sound exists only with its buffer
    };
    // std::deque: adding a sound never moves the others (a sound points at its buffer).
    std::deque<NamedSound> m_sounds;
    CourseMusic m_music; // shared with the older framework's AudioManager
};
