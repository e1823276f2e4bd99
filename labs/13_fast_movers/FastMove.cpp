// FastMove.cpp - your two cures for tunnelling. The wall's counted overlap test, movedBy,
// againstWall and the discrete step are given, in Given.cpp: read discreteStep first.
#include "FastMove.h"

#include <algorithm>
#include <cmath>

// [slide:lab13-sub-steps]
MoveResult subSteppedStep(const Box& bullet, float velocityX, float dt, WallTests& wall,
                          float maxSubStep)
{
    MoveResult result{bullet, false};
    // BEGIN TASK 1: sub-steps
    // Enough equal sub-steps that none is longer than maxSubStep: if maxSubStep is less
    // than the wall's thickness plus the bullet's width, no sub-step can jump the wall.
    const float distance = std::abs(velocityX * dt);
    const int subSteps = std::max(1, static_cast<int>(std::ceil(distance / maxSubStep)));
    const float subMove = velocityX * dt / static_cast<float>(subSteps);
    for (int step = 0; step < subSteps; ++step)
    {
        result.bullet = movedBy(result.bullet, subMove);
        if (wall.overlaps(result.bullet))
        {
            result.bullet = againstWall(result.bullet, velocityX, wall.box());
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
    MoveResult result{bullet, false};
    // BEGIN TASK 2: a speculative contact
    // The wall is ahead only if it is level with the bullet and on the side it moves to.
    // The gap is the free distance; a move shorter than the gap is safe in full, a longer
    // one ends at the gap, exactly touching (Catto, "Speculative
    // contacts", GDC 2013; the platformer article's fix for the bullet through paper).
    const bool level = bullet.top < hitbox::bottomOf(wall) && wall.top < hitbox::bottomOf(bullet);
    const float move = velocityX * dt;
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
    // WallTests tests(wall);
    // result = discreteStep(bullet, velocityX, dt, tests); // one step, one test: tunnels
    // END TASK 2
    return result;
}
// [/slide]
