#include "Framework/Animation.h"

void Animation::addFrame(sf::IntRect frame)
{
    m_frames.push_back(frame);
}

int Animation::getSize() const
{
    return static_cast<int>(m_frames.size());
}

void Animation::setFrameSpeed(float secondsPerFrame)
{
    m_secondsPerFrame = secondsPerFrame;
}

float Animation::getFrameSpeed() const
{
    return m_secondsPerFrame;
}

void Animation::animate(float dt)
{
    if (!m_playing || m_frames.empty() || m_secondsPerFrame <= 0.f)
        return;
    m_secondsInFrame += dt;
    while (m_playing && m_secondsInFrame >= m_secondsPerFrame)
    {
        m_secondsInFrame -= m_secondsPerFrame;
        if (m_currentFrame + 1 < getSize())
            ++m_currentFrame;
        else if (m_looping)
            m_currentFrame = 0;
        else
            m_playing = false;
    }
}

void Animation::reset()
{
    m_currentFrame = 0;
    m_secondsInFrame = 0.f;
}

sf::IntRect Animation::getCurrentFrame() const
{
    if (m_frames.empty())
        return {};
    const sf::IntRect frame = m_frames[static_cast<std::size_t>(m_currentFrame)];
    if (!m_flipped)
        return frame;
    return sf::IntRect({frame.position.x + frame.size.x, frame.position.y},
                       {-frame.size.x, frame.size.y});
}

void Animation::setFlipped(bool flipped)
{
    m_flipped = flipped;
}

bool Animation::getFlipped() const
{
    return m_flipped;
}

void Animation::setLooping(bool looping)
{
    m_looping = looping;
}

bool Animation::getLooping() const
{
    return m_looping;
}

void Animation::setPlaying(bool playing)
{
    m_playing = playing;
}

bool Animation::getPlaying() const
{
    return m_playing;
}

void Animation::stop()
{
    m_playing = false;
    reset();
}

void Animation::pause()
{
    m_playing = false;
}
