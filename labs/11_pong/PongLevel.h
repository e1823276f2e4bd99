// PongLevel.h - a match of Pong: two paddles, a ball, a score.
//
// Each fixed step runs the rules in the order of the lab sheet (update() in PongLevel.cpp):
// the paddles plan their moves, the ball is swept against them, the walls bounce it, and a
// ball past a goal line scores. render() only reads that state.
#pragma once

#include "Ball.h"
#include "Court.h"
#include "Paddle.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"

#include <random>
#include <string>

class PongLevel : public hitbox::Level
{
public:
    // The first serve goes to a random side; `seed` makes every serve's angle repeatable.
    // `players`: 1, you (left) against the computer; 2, two people; 0, the computer plays
    // both sides (a demonstration, and what --headless shows).
    explicit PongLevel(unsigned seed = 1, int players = 1);

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // Task 4: a ball wholly past a goal line (it shares no area with the court: touching
    // the line from outside is out) is a point for the other player, and the next serve
    // goes towards the player who lost the point. A ball still over the line is in play.
    void scoreAndServe();
    // The ball back in the middle, moving at ballSpeed towards the left (`direction` -1)
    // or the right player (+1), at a random angle of up to maxServeDegrees.
    void serveTowards(int direction);

    // The state, for the tests (and for experiments).
    Ball& getBall();
    Paddle& getLeftPaddle();
    Paddle& getRightPaddle();
    int getLeftScore() const;
    int getRightScore() const;
    void setComputerPlaysRight(bool playing);

private:
    Ball ball;
    Paddle left{court.left + paddleInset + paddleWidth / 2.f};
    Paddle right{court.right - paddleInset - paddleWidth / 2.f};
    float leftDirection = 0.f;  // from the keys: -1 up, +1 down
    float rightDirection = 0.f; // the same, when a second player has the right paddle
    bool computerPlaysLeft = false;
    bool computerPlaysRight = true;
    int leftScore = 0;
    int rightScore = 0;
    std::mt19937 random;
    hitbox::LazyFont font;
};
