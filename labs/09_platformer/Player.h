// Player.h - the platformer's player: how the controls change its velocity (acceleration,
// deceleration, a top speed, gravity and a jump).
//
// The player knows nothing about tiles. PlatformerLevel moves it, finds the tiles it went
// into and pushes it back out (see PlatformerLevel.cpp).
#pragma once

#include "TileMap.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Shapes.h"

// What the keys ask for during one step.
struct PlayerControls
{
    bool left = false;
    bool right = false;
    bool jump = false; // pressed (not held): one press, at most one jump
    bool dive = false; // pressed: shoot straight down (to test the speed cap)
};

class Player
{
public:
    // The tuning, in pixels and seconds, where a student can try other values.
    static constexpr float width = 32.f;
    static constexpr float height = 60.f;
    static constexpr float runAcceleration = 2100.f; // px/s^2 while a direction is held
    static constexpr float runDeceleration = 3150.f; // px/s^2 with no direction: stops
                                                     // 50 % faster than it starts
    static constexpr float maxRunSpeed = 420.f;      // px/s
    static constexpr float gravity = 3300.f;         // px/s^2, down
    static constexpr float jumpSpeed = 1140.f;       // px/s, up: about 4 tiles high
    static constexpr float diveSpeed = 13500.f;      // px/s, down: far too fast on purpose
    // The speed cap against tunnelling: in one step the player may move less
    // than one tile, so it cannot jump over a tile between two steps.
    static constexpr float maxFallSpeed = 2250.f; // px/s
    // PlatformerLevel starts the player in the 'P' tile and the empty one above or below it.
    static_assert(height <= 2.f * TileMap::tileSize, "the player must fit in two tiles");
    static_assert(maxFallSpeed * hitbox::stepSeconds < TileMap::tileSize,
                  "the speed cap must keep every step shorter than a tile");

    explicit Player(hitbox::Vec2 startPosition = {});

    // Change the velocity for one step of `dt` seconds from the controls. `grounded` says
    // whether the feet rested on a floor at the end of the last step; `capSpeed` turns the
    // speed cap on (a key in the lab turns it off to show the tunnelling it prevents).
    void steer(const PlayerControls& controls, bool grounded, bool capSpeed, float dt);

    hitbox::Box getBox() const { return {position.x, position.y, width, height}; }
    hitbox::Vec2 getPosition() const { return position; }
    hitbox::Vec2 getVelocity() const { return velocity; }
    void setPosition(hitbox::Vec2 newPosition) { position = newPosition; }
    void setVelocity(hitbox::Vec2 newVelocity) { velocity = newVelocity; }

private:
    hitbox::Vec2 position; // top-left corner of the box, pixels
    hitbox::Vec2 velocity; // pixels per second
};
