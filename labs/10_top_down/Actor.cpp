#include "Actor.h"

#include <cmath>

sf::FloatRect Actor::hitbox() const
{
    return {feet.x - hitboxSize.x / 2.f, feet.y - hitboxSize.y / 2.f, hitboxSize.x, hitboxSize.y};
}

sf::FloatRect Actor::spriteBox() const
{
    const float bottom = feet.y + hitboxSize.y / 2.f;
    return {feet.x - spriteSize.x / 2.f, bottom - spriteSize.y, spriteSize.x, spriteSize.y};
}

float Actor::depth() const
{
    return feet.y + hitboxSize.y / 2.f;
}

sf::Vector2f directionFrom(sf::Vector2f from, sf::Vector2f to)
{
    const sf::Vector2f offset = to - from;
    const float length = std::hypot(offset.x, offset.y);
    if (length == 0.f)
        return {0.f, 1.f};
    return offset / length;
}
