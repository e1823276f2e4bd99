#include "FastMove.h"

#include "hitbox/geometry/Overlap.h"

#include <algorithm>
#include <cmath>

Box movedBy(const Box& box, float dx)
{
    return {box.left + dx, box.top, box.width, box.height};
}

namespace
{
// The bullet put back against the side of the wall it came from.
Box againstWall(const Box& bullet, float velocityX, const Box& wall)
{
    if (velocityX >= 0.f)
        return {wall.left - bullet.width, bullet.top, bullet.width, bullet.height};
    return {hitbox::rightOf(wall), bullet.top, bullet.width, bullet.height};
}
} // namespace

MoveResult discreteStep(const Box& bullet, float velocityX, float dt, const Box& wall)
{
    MoveResult result{movedBy(bullet, velocityX * dt), false, 1};
    if (hitbox::boxVsBox(result.bullet, wall))
        result = {againstWall(result.bullet, velocityX, wall), true, 1};
    return result;
}

// [slide:lab13-sub-steps]
MoveResult subSteppedStep(const Box& bullet, float velocityX, float dt, const Box& wall,
                          float maxSubStep)
{
    MoveResult result{bullet, false, 0};
    // BEGIN TASK 1: sub-steps
    // Enough equal sub-steps that none is longer than maxSubStep: if maxSubStep is less
    // than the wall's thickness plus the bullet's width, no sub-step can jump the wall.
    const float distance = std::abs(velocityX * dt);
    const int subSteps = std::max(1, static_cast<int>(std::ceil(distance / maxSubStep)));
    const float subMove = velocityX * dt / static_cast<float>(subSteps);
    for (int step = 0; step < subSteps; ++step)
    {
        result.bullet = movedBy(result.bullet, subMove);
        ++result.overlapTests;
        if (hitbox::boxVsBox(result.bullet, wall))
        {
            result.bullet = againstWall(result.bullet, velocityX, wall);
            result.hitWall = true;
            break;
        }
    }
    // STARTER TASK 1
    // (void)maxSubStep;
    // result = discreteStep(bullet, velocityX, dt, wall); // one step, one test: tunnels
    // END TASK 1
    return result;
}
// [/slide]

// [slide:lab13-speculative]
MoveResult speculativeStep(const Box& bullet, float velocityX, float dt, const Box& wall)
{
    MoveResult result{bullet, false, 0};
    // BEGIN TASK 2: a speculative contact
    // The wall is ahead only if it is level with the bullet and on the side it moves to.
    // The gap is the free distance; a move shorter than the gap is safe in full, a longer
    // one ends at the gap, exactly touching (Catto, "Speculative
    // contacts", GDC 2013; the platformer article's fix for the bullet through paper).
    const bool level = bullet.top < hitbox::bottomOf(wall) && wall.top < hitbox::bottomOf(bullet);
    const float move = velocityX * dt;
    result.overlapTests = 1;
    if (level && move > 0.f && hitbox::rightOf(bullet) <= wall.left)
    {
        result.hitWall = move >= wall.left - hitbox::rightOf(bullet);
        result.bullet =
            result.hitWall ? againstWall(bullet, velocityX, wall) : movedBy(bullet, move);
        return result;
    }
    if (level && move < 0.f && hitbox::rightOf(wall) <= bullet.left)
    {
        result.hitWall = -move >= bullet.left - hitbox::rightOf(wall);
        result.bullet =
            result.hitWall ? againstWall(bullet, velocityX, wall) : movedBy(bullet, move);
        return result;
    }
    result.bullet = movedBy(bullet, move);
    // STARTER TASK 2
    // result = discreteStep(bullet, velocityX, dt, wall); // one step, one test: tunnels
    // END TASK 2
    return result;
}
// [/slide]
