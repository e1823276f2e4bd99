#include "Score.h"

Side opponentOf(Side side)
{
    return side == Side::Left ? Side::Right : Side::Left;
}

int directionOf(Side side)
{
    return side == Side::Left ? -1 : 1;
}

std::string nameOf(Side side)
{
    return side == Side::Left ? "left" : "right";
}

Score::Score(int pointsNeeded) : pointsToWin(pointsNeeded < 1 ? 1 : pointsNeeded) {}

void Score::addPoint(Side scorer)
{
    if (isMatchOver())
        return; // a finished match stays finished
    if (scorer == Side::Left)
        ++leftPoints;
    else
        ++rightPoints;
}

int Score::pointsOf(Side side) const
{
    return side == Side::Left ? leftPoints : rightPoints;
}

int Score::getPointsToWin() const
{
    return pointsToWin;
}

bool Score::isMatchOver() const
{
    return leftPoints >= pointsToWin || rightPoints >= pointsToWin;
}

Side Score::getWinner() const
{
    return leftPoints >= rightPoints ? Side::Left : Side::Right;
}

void Score::reset()
{
    leftPoints = 0;
    rightPoints = 0;
}

Side Score::serveTowards(Side scorer)
{
    return opponentOf(scorer);
}
