// Ball.h - the ball: a small square GameObject, and how it moves through a step.
//
// The ball's origin is its centre, so getPosition() is the centre.
#pragma once

#include "hitbox/objects/GameObject.h"

class Paddle;

class Ball : public hitbox::GameObject
{
public:
    Ball(); // ballSize square, standing still

    // Puts the ball's centre at `center`, moving at `startVelocity` (pixels per second).
    void placeAt(sf::Vector2f center, sf::Vector2f startVelocity);

    // Task 2: a ball past the court's top or bottom edge is put back against that edge
    // and sent away from it (only the vertical velocity changes, its size kept). Returns
    // true when it bounced. A ball touching an edge is inside: no bounce.
    bool bounceOffWalls();

    // Task 3: the ball hit `other` (a paddle; nullptr, the world, never happens in Pong).
    // It leaves away from the paddle at the same speed, at an angle set only by where it
    // hit: flat from the middle, steeper towards the ends, maxBounceDegrees at most.
    void collisionResponse(hitbox::GameObject* other) override;
};

// Task 5: moves `ball` by velocity * dt, swept against both paddles and the moves they
// have planned this step, so it never passes through one at any speed. At the first hit
// the ball stops touching the paddle, is told (collisionResponse) and moves on with what
// is left of the step. The paddles do not move here (finishMove does that).
void moveBall(Ball& ball, Paddle& left, Paddle& right, float dt);
