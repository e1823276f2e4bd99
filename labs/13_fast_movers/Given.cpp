// Given.cpp - the code given to you in lab 13: the wall's overlap test, which counts itself,
// moving a box, and the plain discrete step. Yours is FastMove.cpp. The grading tests count
// the tests with this file, so the grader always uses the course's copy of it.
#include "FastMove.h"

#include "hitbox/geometry/Overlap.h"

WallTests::WallTests(const Box& box) : wallBox(box) {}

const Box& WallTests::box() const
{
    return wallBox;
}

bool WallTests::overlaps(const Box& bullet)
{
    testedBoxes.push_back(bullet);
    return hitbox::boxVsBox(bullet, wallBox);
}

const std::vector<Box>& WallTests::tested() const
{
    return testedBoxes;
}

Box movedBy(const Box& box, float dx)
{
    return {box.left + dx, box.top, box.width, box.height};
}

Box againstWall(const Box& bullet, float velocityX, const Box& wall)
{
    if (velocityX >= 0.f)
        return {wall.left - bullet.width, bullet.top, bullet.width, bullet.height};
    return {hitbox::rightOf(wall), bullet.top, bullet.width, bullet.height};
}

MoveResult discreteStep(const Box& bullet, float velocityX, float dt, WallTests& wall)
{
    MoveResult result{movedBy(bullet, velocityX * dt), false};
    if (wall.overlaps(result.bullet))
        result = {againstWall(result.bullet, velocityX, wall.box()), true};
    return result;
}
