// Player.h - the platformer's player: how the controls change its velocity (acceleration,
// deceleration, a top speed, gravity and a jump).
//
// The player knows nothing about tiles. PlatformerLevel moves it, finds the tiles it went
// into and pushes it back out (see PlatformerLevel.cpp).
#pragma once

#include "TileMap.h"

#include "hitbox/app/App.h"

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>

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
    static_assert(maxFallSpeed * hitbox::stepSeconds < TileMap::tileSize,
                  "the speed cap must keep every step shorter than a tile");

    explicit Player(sf::Vector2f startPosition = {});

    // Change the velocity for one step of `dt` seconds from the controls. `grounded` says
    // whether the feet rested on a floor at the end of the last step; `capSpeed` turns the
    // speed cap on (a key in the lab turns it off to show the tunnelling it prevents).
    void steer(const PlayerControls& controls, bool grounded, bool capSpeed, float dt);

    sf::FloatRect getBox() const { return {position.x, position.y, width, height}; }
    sf::Vector2f getPosition() const { return position; }
    sf::Vector2f getVelocity() const { return velocity; }
    void setPosition(sf::Vector2f newPosition) { position = newPosition; }
    void setVelocity(sf::Vector2f newVelocity) { velocity = newVelocity; }

private:
    sf::Vector2f position; // top-left corner of the box, pixels
    sf::Vector2f velocity; // pixels per second
};
