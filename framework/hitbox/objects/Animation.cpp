#include "hitbox/objects/Animation.h"

#include "hitbox/sfml/Graphics.h"

#include <cmath>

namespace hitbox
{

void Animation::addFrame(sf::IntRect frame)
{
    frames.push_back(frame);
}

int Animation::getSize() const
{
    return static_cast<int>(frames.size());
}

void Animation::setFrameSpeed(float newSecondsPerFrame)
{
    secondsPerFrame = newSecondsPerFrame;
}

float Animation::getFrameSpeed() const
{
    return secondsPerFrame;
}

void Animation::animate(float dt)
{
    // "!(x > 0)" is also true for NaN: a broken speed or time holds the frame.
    if (!playing || frames.empty() || !(secondsPerFrame > 0.f) || !(dt > 0.f) || !std::isfinite(dt))
        return;
    secondsInFrame += dt;
    if (secondsInFrame < secondsPerFrame)
        return;

    // A long frame (a stall, a breakpoint) may cover several animation frames: count them
    // rather than loop, so a tiny frame speed cannot hang the game.
    // (In double: a tiny speed must not make the count overflow to infinity.)
    const double framesPassed = std::floor(static_cast<double>(secondsInFrame) / secondsPerFrame);
    secondsInFrame = std::fmod(secondsInFrame, secondsPerFrame);
    const double nextFrame = currentFrame + framesPassed;
    if (nextFrame < getSize())
    {
        currentFrame = static_cast<int>(nextFrame);
    }
    else if (looping)
    {
        currentFrame = static_cast<int>(std::fmod(nextFrame, getSize()));
    }
    else
    {
        // Stay on the last frame and stop, as the old framework did.
        currentFrame = getSize() - 1;
        secondsInFrame = 0.f;
        playing = false;
    }
}

void Animation::reset()
{
    currentFrame = 0;
    secondsInFrame = 0.f;
}

sf::IntRect Animation::getCurrentFrame() const
{
    if (frames.empty())
        return {};
    const sf::IntRect frame = frames[static_cast<std::size_t>(currentFrame)];
    if (!flipped)
        return frame;
    // Start at the right edge and run leftwards: the texture is read mirrored.
    const sf::Vector2i position = hitbox::rectPosition(frame);
    const sf::Vector2i size = hitbox::rectSize(frame);
    return sf::IntRect({position.x + size.x, position.y}, {-size.x, size.y});
}

int Animation::getCurrentFrameIndex() const
{
    return currentFrame;
}

void Animation::setFlipped(bool isFlipped)
{
    flipped = isFlipped;
}

bool Animation::getFlipped() const
{
    return flipped;
}

void Animation::setLooping(bool isLooping)
{
    looping = isLooping;
}

bool Animation::getLooping() const
{
    return looping;
}

void Animation::setPlaying(bool isPlaying)
{
    playing = isPlaying;
}

bool Animation::getPlaying() const
{
    return playing;
}

bool Animation::isPlaying() const
{
    return playing;
}

void Animation::stop()
{
    playing = false;
    reset();
}

void Animation::pause()
{
    playing = false;
}

} // namespace hitbox
