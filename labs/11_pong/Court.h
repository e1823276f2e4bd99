// Court.h - the numbers to play with, and the court they describe.
//
// Every rule of the lab reads its numbers from here, and so do the grading tests: change
// any of them and the tests still check the same behaviour. Pixels and seconds.
#pragma once

#include "hitbox/app/Level.h" // hitbox::defaultWorldSize: the size of the world

// The court: the ball and the paddles stay between `top` and `bottom` (the walls); `left`
// and `right` are the goal lines. Touching an edge is inside (Hitbox's edge rule: touching
// is not overlapping).
struct Court
{
    float left;
    float top;
    float right;
    float bottom;
};

// The numbers to play with. The court is as wide as the world; below it, the bottom wall
// and the help line.
inline const Court court{0.f, 24.f, hitbox::defaultWorldSize.x, 640.f};
constexpr float paddleWidth = 16.f;
constexpr float paddleHeight = 96.f;
constexpr float paddleInset = 48.f;  // from the goal line to the paddle
constexpr float paddleSpeed = 520.f; // pixels per second, a key held down
constexpr float ballSize = 14.f;     // the ball is a square, as in 1972
constexpr float ballSpeed = 480.f;   // pixels per second; a return keeps the speed
// The steepest return, off the very end of a paddle, in degrees from the horizontal. Less
// than 90, so the ball never goes straight up and down and every rally reaches a goal.
constexpr float maxBounceDegrees = 60.f;
constexpr float maxServeDegrees = 30.f; // a serve leaves at a random angle up to this
// The computer's paddle moves at most this fraction of paddleSpeed: it cannot reach a
// ball placed far from it in time, so it can be beaten.
constexpr float computerTopSpeed = 0.6f;
