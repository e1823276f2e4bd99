#include "Platforms.h"

#include <algorithm>

hitbox::OneWayStop landOnOneWay(const hitbox::Box& player, hitbox::Vec2 move,
                                const hitbox::Box& platform)
{
    // BEGIN TASK 5: a one-way platform stops only a fall that started above its top
    hitbox::OneWayStop stop{false, move};
    if (move.y <= 0.f)
        return stop; // not falling: standing still, or jumping up through it
    // Where the player's bottom was when the step BEGAN, not where the move takes it: a player
    // jumping up through the platform must not be caught half-way.
    const float bottom = player.top + player.height;
    if (bottom > platform.top)
        return stop; // started below the top: passes through
    if (bottom + move.y <= platform.top)
        return stop; // ends above the top, or exactly on it (touching)
    // Over the platform when the bottom reaches the top (t of the move)?
    const float t = (platform.top - bottom) / move.y;
    const float left = player.left + move.x * t;
    if (!(left < platform.left + platform.width && platform.left < left + player.width))
        return stop; // beside it, or only touching its end: falls past
    stop.blocked = true;
    stop.move.y = platform.top - bottom;
    return stop;
    // STARTER TASK 5
    // (void)player;
    // (void)platform;
    // return hitbox::OneWayStop{false, move}; // for now a one-way platform is not there
    // END TASK 5
}

hitbox::SlopeFoot footOnSlope(const hitbox::Box& player, float velocityY,
                              const hitbox::Slope& slope, float snapDistance)
{
    // BEGIN TASK 6: stand the player's foot on a slope
    hitbox::SlopeFoot foot;
    if (velocityY < 0.f)
        return foot; // rising: a jump leaves the slope, it is never pulled back onto it
    // One point decides, the middle of the bottom: the corners may hang over the slope.
    const float footX = player.left + player.width / 2.f;
    const float footY = player.top + player.height;
    const hitbox::SlopeGround ground = hitbox::slopeGroundAt(slope, footX);
    if (!ground.over || footY > std::max(slope.left.y, slope.right.y))
        return foot; // beside the slope, or under it (in the tile below)
    // How far the foot is above the surface (negative: inside the slope).
    const float above = ground.y - footY;
    if (above > snapDistance)
        return foot; // too high to pull down: in the air
    foot.grounded = true;
    foot.moveY = above; // down onto the surface, or up out of the slope
    return foot;
    // STARTER TASK 6
    // (void)player;
    // (void)velocityY;
    // (void)slope;
    // (void)snapDistance;
    // return hitbox::SlopeFoot{}; // for now a slope is not there: the player falls into it
    // END TASK 6
}
