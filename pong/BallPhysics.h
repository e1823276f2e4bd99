// BallPhysics.h - move the ball for one step without ever passing through anything.
//
// A discrete test only sees where the ball ends up, so a fast ball can jump over a 16-pixel
// paddle between two steps (at 2000 px/s it moves 17 px per step). Instead the ball's whole
// move is SWEPT (hitbox/geometry/Sweep.h) against both walls and both moving paddles; the
// earliest hit wins, the ball moves to it, bounces (Ball::collisionResponse), and the rest
// of the step is swept again from there. So it is safe at any speed and any frame rate.
#pragma once

#include "Arena.h"
#include "Ball.h"
#include "GameEvents.h"
#include "Paddle.h"

#include "hitbox/geometry/Sweep.h"

#include <vector>

// More bounces than this in one step and the rest of that step's move is dropped (it takes
// a ball caught between a paddle's end and a wall; it moves on next step).
constexpr int maxBouncesPerStep = 8;

struct BallStep
{
    std::vector<GameEvent> events; // PaddleHit / WallHit, in the order they happened
    hitbox::Hit lastHit;           // the last hit this step (hit == false if none)
    int bounces = 0;
};

// Moves `ball` by velocity * dt, bouncing off the walls and off the paddles' planned moves
// (Paddle::planMove must have been called this step; the paddles themselves do not move).
BallStep moveBall(Ball& ball, Paddle& left, Paddle& right, const Arena& arena, float dt);
