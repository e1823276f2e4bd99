#include "Framework/AudioManager.h"

AudioManager::AudioManager() = default;

AudioManager::~AudioManager()
{
    stopAllSounds();
    stopAllMusic();
}

void AudioManager::addSound(std::string filename, std::string lname)
{
    sounds.emplace_back();
    sounds.back().loadSound(filename, lname);
}

void AudioManager::playSoundbyName(std::string lname)
{
    if (sf::Sound* sound = getSound(lname))
        sound->play();
}

void AudioManager::stopAllSounds()
{
    for (SoundObject& soundObject : sounds)
        soundObject.sound.stop();
}

sf::Sound* AudioManager::getSound(std::string lname)
{
    for (SoundObject& soundObject : sounds)
        if (soundObject.name == lname)
            return &soundObject.sound;
    return nullptr;
}

void AudioManager::addMusic(std::string filename, std::string lname)
{
    music.add(filename, lname);
}

void AudioManager::playMusicbyName(std::string lname)
{
    music.play(lname);
}

void AudioManager::stopAllMusic()
{
    music.stream().stop();
}

sf::Music* AudioManager::getMusic()
{
    return &music.stream();
}
