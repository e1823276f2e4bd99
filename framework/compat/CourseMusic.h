// CourseMusic.h - the music half of both generations' AudioManager (Framework/AudioManager.h,
// course2025/Framework/AudioManager.h): pieces added by name, one streamed at a time, on a
// loop. Each AudioManager keeps one and adds its generation's signatures.
#pragma once

#include "hitbox/sfml/Audio.h"

#include <SFML/Audio/Music.hpp>

#include <string>
#include <vector>

class CourseMusic
{
public:
    void add(const std::string& filename, const std::string& name)
    {
        pieces.push_back({name, filename});
    }

    // Stops the music playing now and streams the named piece from its start, looping. A
    // name never added changes nothing; a file that does not open leaves the music stopped
    // (SFML prints one line saying which).
    void play(const std::string& name)
    {
        for (const Piece& piece : pieces)
        {
            if (piece.name != name)
                continue;
            music.stop();
            if (music.openFromFile(piece.filename))
            {
                hitbox::setLooping(music, true);
                music.play();
            }
            return;
        }
    }

    // The stream itself, to stop it or change its volume.
    sf::Music& stream() { return music; }

private:
    struct Piece
    {
        std::string name;
        std::string filename;
    };
    std::vector<Piece> pieces;
    sf::Music music;
};
