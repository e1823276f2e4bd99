// Paddle.h - a paddle: a tall GameObject that moves up and down between the walls.
//
// Moving is split in two so the ball can be swept against a MOVING paddle:
//   1. planMove(): decide where the paddle goes this step (velocity, clamped to the walls);
//   2. the ball is swept against the paddle's box and that planned move (BallPhysics.cpp);
//   3. finishMove(): actually move, stopping early if the ball is in the way.
// A human (keys) and a computer (Opponent) both steer it the same way: with an "intent"
// from -1 (full speed up) to +1 (full speed down).
#pragma once

#include "Arena.h"

#include "hitbox/objects/GameObject.h"

struct PaddleSettings
{
    sf::Vector2f size{16.f, 96.f};
    float speed = 620.f;           // pixels per second at full intent
    float distanceFromEdge = 48.f; // gap between the screen edge and the paddle
    // The paddle stops this far short of each wall, leaving room for the ball to pass
    // between its end and the wall. With no room, a ball could be pinned there, bouncing
    // between paddle and wall forever. (The 1972 original's paddles did not reach the top
    // either.) Keep it larger than the ball.
    float wallGap = 20.f;
};

class Paddle : public hitbox::GameObject
{
public:
    // side: -1 the left paddle, +1 the right one.
    Paddle(int side, const Arena& arena, const PaddleSettings& settings = {});

    void placeAtStart(const Arena& arena); // vertically centred
    // Steps 1 and 3 above. intent is clamped to [-1, 1].
    void planMove(float intent, const Arena& arena, float dt);
    void finishMove(const sf::FloatRect& ballBox);

    sf::Vector2f getPlannedMove() const; // this step's displacement, pixels
    int getSide() const;
    const PaddleSettings& getSettings() const;

private:
    PaddleSettings settings;
    int side;
    sf::Vector2f plannedMove;
};
