// SquaresLevel.h - crates bouncing off the window edges and off each other, by their boxes.
//
// It starts like the lecture's example: two squares on one line, flying at each other.
// Space adds more (or start with --squares N).
#pragma once

#include "Square.h"

#include "hitbox/app/Level.h"

#include <random>
#include <string>
#include <vector>

class SquaresLevel : public hitbox::Level
{
public:
    // `squareCount` squares: the first two fly at each other, the rest start in random
    // places (from `seed`) moving diagonally, all at squareSpeed.
    explicit SquaresLevel(int squareCount = 2, unsigned seed = 1);
    // Space adds squares up to this many (and --squares accepts 2 to this many).
    static constexpr int maxSquares = 40;

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // For the grading tests (and for experiments): set up any squares you like.
    void removeAllSquares();
    void addSquare(sf::Vector2f center, sf::Vector2f velocity);
    int getSquareCount() const;
    const Square& getSquare(int index) const;

private:
    void startWithTwoSquares();
    // Adds a square where its picture overlaps no other, moving diagonally.
    void addRandomSquare();

    std::vector<Square> squares;
    std::mt19937 random;
};
