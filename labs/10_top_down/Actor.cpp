#include "Actor.h"

#include <cmath>

hitbox::Box Actor::hitbox() const
{
    return {feet.x - hitboxSize.x / 2.f, feet.y - hitboxSize.y / 2.f, hitboxSize.x, hitboxSize.y};
}

hitbox::Box Actor::spriteBox() const
{
    const float bottom = feet.y + hitboxSize.y / 2.f;
    return {feet.x - spriteSize.x / 2.f, bottom - spriteSize.y, spriteSize.x, spriteSize.y};
}

float Actor::depth() const
{
    return feet.y + hitboxSize.y / 2.f;
}

hitbox::Vec2 directionFrom(hitbox::Vec2 from, hitbox::Vec2 to)
{
    const hitbox::Vec2 offset = to - from;
    const float length = std::hypot(offset.x, offset.y);
    if (length == 0.f)
        return {0.f, 1.f};
    return offset / length;
}
