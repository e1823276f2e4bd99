// BallsLevel.h - balls bouncing off the window edges and off each other.
//
// It starts like the lecture's example: two balls on one line, flying towards each other.
// Space adds more (or start with --balls N) to see many bounce at once.
#pragma once

#include "Ball.h"

#include "hitbox/app/Level.h"

#include <random>
#include <string>
#include <vector>

class BallsLevel : public hitbox::Level
{
public:
    // `ballCount` balls: the first two fly at each other, the rest start in random places
    // (from `seed`) in random directions, all at ballSpeed.
    explicit BallsLevel(int ballCount = 2, unsigned seed = 1);
    // Space adds balls up to this many (and --balls accepts 2 to this many).
    static constexpr int maxBalls = 60;

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // For the grading tests (and for experiments): set up any balls you like.
    void removeAllBalls();
    void addBall(sf::Vector2f center, sf::Vector2f velocity);
    int getBallCount() const;
    const Ball& getBall(int index) const;

private:
    void startWithTwoBalls();
    // Adds a ball where it overlaps no other ball, moving in a random direction.
    void addRandomBall();

    std::vector<Ball> balls;
    std::mt19937 random;
};
