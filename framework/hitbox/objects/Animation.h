// Animation.h - a list of frames on a sprite sheet, played at a steady speed.
//
// Each frame is the rectangle of the texture to show (sf::IntRect, in texture pixels).
// Typical use, as in the course's labs:
//     walk.addFrame(sf::IntRect({0, 0}, {15, 21}));
//     walk.addFrame(sf::IntRect({15, 0}, {15, 21}));
//     walk.setFrameSpeed(1.f / 10.f);          // seconds per frame: 10 frames a second
//     ...every frame:
//     walk.animate(dt);
//     setTextureRect(walk.getCurrentFrame());
#pragma once

#include <SFML/Graphics/Rect.hpp>

#include <vector>

namespace hitbox
{

class Animation
{
public:
    // Appends a frame: the rectangle of the texture to show, in texture pixels.
    void addFrame(sf::IntRect frame);
    [[nodiscard]] int getSize() const; // the number of frames

    // How long each frame shows, in seconds (despite the old name: not frames per second).
    // Zero or less: the animation holds its current frame.
    void setFrameSpeed(float secondsPerFrame);
    [[nodiscard]] float getFrameSpeed() const;

    // Moves on by dt seconds: as many frames as that time covers, keeping the leftover time
    // for the next call, so the speed does not depend on the frame rate. At the last frame a
    // looping animation starts again; one that does not loop stops there (isPlaying() turns
    // false).
    void animate(float dt);
    // Back to the first frame, with no time carried over (playing is not changed).
    void reset();

    // The rectangle to pass to setTextureRect. Flipped: the same frame mirrored left to
    // right (a negative width, which SFML draws mirrored). No frames: an empty rectangle.
    [[nodiscard]] sf::IntRect getCurrentFrame() const;
    [[nodiscard]] int getCurrentFrameIndex() const;

    // Flipped: getCurrentFrame() is mirrored left to right. Looping: after the last frame
    // comes the first (otherwise it stops on the last). Playing: animate() moves on.
    void setFlipped(bool isFlipped);
    [[nodiscard]] bool getFlipped() const;
    void setLooping(bool isLooping);
    [[nodiscard]] bool getLooping() const;
    void setPlaying(bool isPlaying);
    [[nodiscard]] bool getPlaying() const;
    [[nodiscard]] bool isPlaying() const;
    void stop();  // stops playing and goes back to the first frame
    void pause(); // stops playing and keeps the frame: setPlaying(true) carries on from it

private:
    std::vector<sf::IntRect> frames;
    int currentFrame = 0;
    float secondsPerFrame = 0.1f;
    float secondsInFrame = 0.f; // time spent on the current frame so far
    bool flipped = false;
    bool looping = true;
    bool playing = true;
};

} // namespace hitbox
