#include "Paddle.h"

#include "hitbox/geometry/Sweep.h"

#include <algorithm>

Paddle::Paddle(int paddleSide, const Arena& arena, const PaddleSettings& paddleSettings)
    : settings(paddleSettings), side(paddleSide < 0 ? -1 : 1)
{
    setSize(settings.size);
    setOrigin(settings.size / 2.f);
    setCollisionBox(-settings.size.x / 2.f, -settings.size.y / 2.f, settings.size.x,
                    settings.size.y);
    setFillColor(side < 0 ? sf::Color(120, 200, 255) : sf::Color(255, 170, 90));
    placeAtStart(arena);
}

void Paddle::placeAtStart(const Arena& arena)
{
    const float fromEdge = settings.distanceFromEdge + settings.size.x / 2.f;
    const float x = side < 0 ? fromEdge : arena.size.x - fromEdge;
    setPosition({x, arena.centerY()});
    setVelocity(0.f, 0.f);
    plannedMove = {};
}

void Paddle::planMove(float intent, const Arena& arena, float dt)
{
    intent = std::max(-1.f, std::min(1.f, intent));
    // Clamp the target so the paddle stops short of the walls (see wallGap).
    const float reach = settings.size.y / 2.f + settings.wallGap;
    const float wantedY = getPosition().y + intent * settings.speed * dt;
    const float allowedY =
        std::max(arena.playTop() + reach, std::min(arena.playBottom() - reach, wantedY));
    plannedMove = {0.f, allowedY - getPosition().y};
    setVelocity(dt > 0.f ? plannedMove / dt : sf::Vector2f());
}

void Paddle::finishMove(const sf::FloatRect& ballBox)
{
    // The ball has already moved this step. If the paddle would now run into it (the ball
    // sits between the paddle's end and a wall), stop where they touch: a paddle never
    // pushes through the ball.
    const hitbox::Hit blocked = hitbox::sweepBoxVsBox(
        hitbox::toBox(getCollisionBox()), hitbox::toVec2(plannedMove), hitbox::toBox(ballBox));
    const float fraction = blocked.hit ? blocked.time : 1.f;
    move(plannedMove * fraction);
    plannedMove = {};
}

sf::Vector2f Paddle::getPlannedMove() const
{
    return plannedMove;
}

int Paddle::getSide() const
{
    return side;
}

const PaddleSettings& Paddle::getSettings() const
{
    return settings;
}
