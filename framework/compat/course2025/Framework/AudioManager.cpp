#include "Framework/AudioManager.h"

AudioManager::~AudioManager()
{
    stopAllSounds();
    stopAllMusic();
}

void AudioManager::addSound(const std::string& filename, const std::string& name)
{
    NamedSound& added = m_sounds.emplace_back();
    added.name = name;
    if (added.buffer.loadFromFile(filename))
        added.sound.emplace(added.buffer);
}

void AudioManager::playSoundbyName(const std::string& name)
{
    if (sf::Sound* sound = getSound(name))
        sound->play();
}

void AudioManager::stopAllSounds()
{
    for (NamedSound& named : m_sounds)
        if (named.sound)
            named.sound->stop();
}

sf::Sound* AudioManager::getSound(const std::string& name)
{
    for (NamedSound& named : m_sounds)
        if (named.name == name && named.sound)
            return &*named.sound;
    return nullptr;
}

void AudioManager::addMusic(const std::string& filename, const std::string& name)
{
    m_music.add(filename, name);
}

void AudioManager::playMusicbyName(const std::string& name)
{
    m_music.play(name);
}

void AudioManager::stopAllMusic()
{
    m_music.stream().stop();
}

sf::Music& AudioManager::getMusic()
{
    return m_music.stream();
}
