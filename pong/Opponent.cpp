#include "Opponent.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

std::string nameOf(Difficulty difficulty)
{
    switch (difficulty)
    {
    case Difficulty::Easy:
        return "easy";
    case Difficulty::Hard:
        return "hard";
    default:
        return "normal";
    }
}

Difficulty difficultyFromName(const std::string& name)
{
    for (Difficulty difficulty : {Difficulty::Easy, Difficulty::Normal, Difficulty::Hard})
        if (nameOf(difficulty) == name)
            return difficulty;
    throw std::invalid_argument("--difficulty must be easy, normal or hard, not '" + name + "'");
}

Difficulty nextDifficulty(Difficulty difficulty)
{
    if (difficulty == Difficulty::Easy)
        return Difficulty::Normal;
    if (difficulty == Difficulty::Normal)
        return Difficulty::Hard;
    return Difficulty::Easy;
}

OpponentSkill skillFor(Difficulty difficulty)
{
    // Tuned against scripted players (tests/pong/OpponentTests.cpp): Easy is an even match
    // for a weak player, Normal beats the weak one, Hard is an even match for a decent one.
    switch (difficulty)
    {
    case Difficulty::Easy:
        return {0.30f, 0.55f, 40.f, false};
    case Difficulty::Hard:
        return {0.05f, 1.00f, 20.f, true};
    default:
        return {0.15f, 0.80f, 30.f, true};
    }
}

Opponent::Opponent(Difficulty level, unsigned seed)
    : difficulty(level), skill(skillFor(level)), random(seed)
{
}

float Opponent::randomBetween(float low, float high)
{
    // std::uniform_real_distribution may differ between standard libraries; this does not,
    // so a seed replays the same match everywhere.
    const float unit = static_cast<float>(random() % 1000001u) / 1000000.f;
    return low + (high - low) * unit;
}

float Opponent::predictArrivalY(const Ball& ball, const Paddle& paddle, const Arena& arena) const
{
    const sf::Vector2f position = ball.getPosition();
    const sf::Vector2f velocity = ball.getVelocity();
    if (!skill.readsBounces || velocity.x == 0.f)
        return position.y; // just follow the ball
    // Straight line to the paddle's x, then fold it back into the field at every wall
    // (a bounce is a mirror image).
    const float secondsToArrive = (paddle.getPosition().x - position.x) / velocity.x;
    const float half = ball.getSettings().size / 2.f;
    const float top = arena.playTop() + half;
    const float height = arena.playBottom() - half - top;
    float y = position.y + velocity.y * secondsToArrive - top;
    y = std::fmod(y, 2.f * height);
    if (y < 0.f)
        y += 2.f * height;
    if (y > height)
        y = 2.f * height - y;
    return top + y;
}

float Opponent::decide(const Ball& ball, const Paddle& paddle, const Arena& arena, float dt)
{
    secondsUntilNextLook -= dt;
    if (secondsUntilNextLook <= 0.f || targetY < 0.f)
    {
        secondsUntilNextLook = skill.reactionSeconds;
        const bool comingTowardsMe =
            ball.getVelocity().x * static_cast<float>(paddle.getSide()) > 0.f;
        if (comingTowardsMe)
        {
            // The ball has just turned towards us: pick this shot's mistake (which also
            // decides where on the paddle it lands, and so the angle it goes back at).
            // A faster ball is harder to judge: the mistake grows with the ball's speed.
            if (!wasComingTowardsMe)
            {
                const float speedFactor = ball.getSpeed() / ball.getSettings().serveSpeed;
                const float error = skill.aimError * speedFactor;
                aimOffset = randomBetween(-error, error);
            }
            targetY = predictArrivalY(ball, paddle, arena) + aimOffset;
        }
        else
        {
            // The better players wait in the middle; the easy one drifts after the ball.
            targetY = skill.readsBounces ? arena.centerY() : ball.getPosition().y;
        }
        wasComingTowardsMe = comingTowardsMe;
    }
    // Move towards the target, easing off near it so the paddle does not jitter.
    const float gap = targetY - paddle.getPosition().y;
    const float slowDownDistance = 24.f;
    const float intent = std::max(-1.f, std::min(1.f, gap / slowDownDistance));
    return intent * skill.topSpeed;
}

Difficulty Opponent::getDifficulty() const
{
    return difficulty;
}

float Opponent::getTargetY() const
{
    return targetY;
}
