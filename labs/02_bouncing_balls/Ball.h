// Ball.h - a ball that flies in a straight line and bounces off the edges of the world.
//
// A Ball is a GameObject whose origin is its centre, so getPosition() is the centre and the
// bounding circle (by default the circle inside the collision box) is the ball itself.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/objects/GameObject.h"

// The numbers to play with.
constexpr float ballRadius = 28.f; // pixels
constexpr float ballSpeed = 260.f; // pixels per second, every ball's speed at the start

class Ball : public hitbox::GameObject
{
public:
    Ball(sf::Vector2f center, sf::Vector2f startVelocity, sf::Color color);

    // Moves the ball, then keeps it inside the world (the walls are the world's edges).
    void update(float dt) override;
    // Something hit the ball: another ball, or a wall when `other` is nullptr.
    void collisionResponse(hitbox::GameObject* other) override;

    void setWorldSize(sf::Vector2f size);
    float getRadius() const;
    // How many hits collisionResponse has been told about (walls and balls).
    int getHitCount() const;
    // 1 just after a hit, fading to 0: render() flashes the ball with it.
    float getFlash() const;

private:
    sf::Vector2f worldSize = hitbox::defaultWorldSize;
    int hitCount = 0;
    float flash = 0.f;
};

// Two equal balls that overlap bounce apart like billiard balls: pushed apart until they
// just touch, and their velocities along the line between the centres exchanged.
// Balls that do not overlap are left alone.
void bounceApart(Ball& first, Ball& second);
