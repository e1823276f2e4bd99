#include "Player.h"

#include <algorithm>
#include <cmath>

Player::Player(hitbox::Vec2 startPosition) : position(startPosition) {}

void Player::steer(const PlayerControls& controls, bool grounded, bool capSpeed, float dt)
{
    // Run: accelerate towards the held direction; with none held, brake towards zero
    // without overshooting (a brake that overshoots makes the player wobble on the spot).
    if (controls.left != controls.right)
        velocity.x += (controls.right ? runAcceleration : -runAcceleration) * dt;
    else if (velocity.x > 0.f)
        velocity.x = std::max(0.f, velocity.x - runDeceleration * dt);
    else
        velocity.x = std::min(0.f, velocity.x + runDeceleration * dt);
    velocity.x = std::clamp(velocity.x, -maxRunSpeed, maxRunSpeed);

    // BEGIN TASK 1: gravity, and a jump only from the ground
    velocity.y += gravity * dt;
    // Only a player standing on something can push off it: no jumping in mid-air.
    if (controls.jump && grounded)
        velocity.y = -jumpSpeed;
    // STARTER TASK 1
    // (void)grounded;
    // END TASK 1

    if (controls.dive && !grounded)
        velocity.y = diveSpeed;

    // BEGIN TASK 4: cap the speed so no step is longer than a tile
    if (capSpeed)
        velocity.y = std::clamp(velocity.y, -maxFallSpeed, maxFallSpeed);
    // STARTER TASK 4
    // (void)capSpeed;
    // END TASK 4
}
