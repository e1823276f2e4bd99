// Framework/Animation.h (2025-26 course framework) - frames of a sprite sheet played at a
// steady speed, as in the older framework (Hitbox's hitbox/objects/Animation.h), with
// SFML 3's rectangles and the course's stop() and pause().
#pragma once

#include <SFML/Graphics/Rect.hpp>

#include <vector>

class Animation
{
public:
    void addFrame(sf::IntRect frame);
    int getSize() const; // the number of frames

    // Seconds each frame shows. Zero or less: the animation holds its frame.
    void setFrameSpeed(float secondsPerFrame);
    float getFrameSpeed() const;

    // Moves on by dt seconds, keeping leftover time for the next call. At the last frame a
    // looping animation starts again; one that does not loop stops there.
    void animate(float dt);
    void reset(); // back to the first frame
    // The frame to show; flipped, mirrored left to right (a negative width). No frames: empty.
    sf::IntRect getCurrentFrame() const;

    void setFlipped(bool flipped);
    bool getFlipped() const;
    void setLooping(bool looping);
    bool getLooping() const;
    void setPlaying(bool playing);
    bool getPlaying() const;
    void stop();  // stop playing and go back to the first frame
    void pause(); // stop playing, keeping the frame

private:
    std::vector<sf::IntRect> m_frames;
    int m_currentFrame = 0;
    float m_secondsPerFrame = 0.1f;
    float m_secondsInFrame = 0.f;
    bool m_flipped = false;
    bool m_looping = true;
    bool m_playing = true;
};
