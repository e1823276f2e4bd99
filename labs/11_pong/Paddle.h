// Paddle.h - a paddle: a tall GameObject that moves up and down inside the court.
//
// A step moves a paddle in two halves, so the ball can be swept against a MOVING paddle:
// first the level plans the move (setPlannedMove), then the ball is swept against the
// paddle and that move (task 5), then finishMove() makes it.
#pragma once

#include "Ball.h"

#include "hitbox/objects/GameObject.h"

class Paddle : public hitbox::GameObject
{
public:
    // A paddle whose centre stands at `centerX`, halfway down the court.
    explicit Paddle(float centerX);

    // Task 1: this step's move for `direction` (-1 up, +1 down, 0 still; beyond +-1 counts
    // as +-1): direction * paddleSpeed * dt, cut short so the paddle stays inside the
    // court. Ending exactly touching the top or bottom edge is allowed, past it never.
    sf::Vector2f moveWithinCourt(float direction, float dt) const;

    // The move this step will make, and making it.
    void setPlannedMove(sf::Vector2f move);
    sf::Vector2f getPlannedMove() const;
    void finishMove();

private:
    sf::Vector2f plannedMove;
};

// Task 6: the computer player: which way to move `paddle` this step, like a key would
// (-1 up .. +1 down), never faster than computerTopSpeed. It follows a ball coming
// towards it and goes back to the middle while the ball moves away.
float computerDirection(const Ball& ball, const Paddle& paddle, float dt);
