// PongTestHelpers.h - drive a PongLevel the way hitbox::App does, with scripted keys.
#pragma once

#include "PongLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"

#include <functional>

namespace pongtest
{

// One fixed step with these keys held, exactly as the window loop runs it.
inline void step(PongLevel& pong, hitbox::Input& input)
{
    pong.handleInput(input, hitbox::stepSeconds);
    pong.update(hitbox::stepSeconds);
    input.update();
}

inline void steps(PongLevel& pong, long long count)
{
    hitbox::Input input;
    for (long long i = 0; i < count; ++i)
        step(pong, input);
}

inline long long stepsFor(float seconds)
{
    return static_cast<long long>(seconds * hitbox::stepsPerSecond);
}

// Hold `up` or `down` (or neither) so the paddle heads for `targetY`.
inline void steerTowards(hitbox::Input& input, float paddleY, float targetY, float deadZone)
{
    input.setKeyUp(sf::Keyboard::Key::W);
    input.setKeyUp(sf::Keyboard::Key::S);
    if (targetY < paddleY - deadZone)
        input.setKeyDown(sf::Keyboard::Key::W);
    else if (targetY > paddleY + deadZone)
        input.setKeyDown(sf::Keyboard::Key::S);
}

// A person playing the left paddle; decides the keys from what is on screen.
using Player = std::function<void(const PongLevel&, hitbox::Input&)>;

// Plays one-player matches until the first is won (or `maxSeconds` pass). Returns the
// winner, or nothing in `finished` if nobody won in time.
inline Side playMatch(PongLevel& pong, const Player& player, float maxSeconds, bool& finished)
{
    hitbox::Input input;
    const long long limit = stepsFor(maxSeconds);
    for (long long i = 0; i < limit && pong.getScreen() == Screen::Play; ++i)
    {
        player(pong, input);
        step(pong, input);
    }
    finished = pong.getScreen() == Screen::Win;
    return pong.getScore().getWinner();
}

} // namespace pongtest
