// Score.h - the rules of a match: who has how many points, who won, who is served to.
#pragma once

#include <string>

// The two players. Left plays the left paddle (W/S), right the right paddle (Up/Down).
enum class Side
{
    Left,
    Right
};

Side opponentOf(Side side);
// -1 for Left, +1 for Right: the x direction towards that side's goal.
int directionOf(Side side);
std::string nameOf(Side side); // "left", "right"

class Score
{
public:
    explicit Score(int pointsToWin = 11);

    void addPoint(Side scorer);
    int pointsOf(Side side) const;
    int getPointsToWin() const;
    bool isMatchOver() const;
    Side getWinner() const; // only meaningful when isMatchOver()
    void reset();

    // After a point the ball is served TOWARDS the player who lost it: they had the worse
    // of the rally, so they get the first touch of the next one.
    static Side serveTowards(Side scorer);

private:
    int pointsToWin;
    int leftPoints = 0;
    int rightPoints = 0;
};
