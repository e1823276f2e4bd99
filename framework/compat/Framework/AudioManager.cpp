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
    musics.emplace_back();
    musics.back().setMusic(filename, lname);
}

void AudioManager::playMusicbyName(std::string lname)
{
    for (const MusicObject& musicObject : musics)
    {
        if (musicObject.name != lname)
            continue;
        music.stop();
        if (music.openFromFile(musicObject.filename))
        {
            music.setLoop(true);
            music.play();
        }
        return;
    }
}

void AudioManager::stopAllMusic()
{
    music.stop();
}

sf::Music* AudioManager::getMusic()
{
    return &music;
}
