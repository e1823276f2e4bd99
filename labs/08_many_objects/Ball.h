// Ball.h - one ball of the many-objects lab: a circle that moves, plus the collision
// filter (layer and mask) that decides which other balls it may ever touch.
#pragma once

#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/geometry/Shapes.h"

#include <cstdint>

// What a ball is in the game. Only the layers scene uses the last three.
enum class BallKind
{
    Plain,
    Ship,
    Bullet,
    Pickup
};

struct Ball
{
    hitbox::Vec2 position; // centre, world pixels
    hitbox::Vec2 velocity; // pixels per second
    float radius = 4.f;
    BallKind kind = BallKind::Plain;
    int owner = 0; // which ship a ship or a bullet belongs to (0 or 1)
    std::uint32_t layer = 1;
    std::uint32_t mask = 0xFFFFFFFF;
    float age = 0.f;   // seconds since it appeared (bullets expire)
    int responses = 0; // collision responses in the last step

    hitbox::Circle circle() const { return {position, radius}; }
    // The cheap bound the broadphase sorts and buckets: the square around the circle.
    hitbox::Box box() const
    {
        return {position.x - radius, position.y - radius, 2.f * radius, 2.f * radius};
    }
    hitbox::BroadphaseItem item() const { return {box(), layer, mask}; }
};

// Push two overlapping balls apart (half the depth each) and, if they are moving towards
// each other, swap their speeds along the contact normal: an elastic bounce between equal
// masses. `contact` is circleVsCircleContact(a, b): its normal points from b towards a.
void bounceApart(Ball& a, Ball& b, const hitbox::Contact& contact);
