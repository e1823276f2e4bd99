#include "BallPhysics.h"

namespace
{
// Pushed out of an overlap, the ball is moved this much further: a float position can
// round back to a hair inside, and a ball a hair inside is "hit" again every step.
const float separationSkin = 0.01f;

// One thing the ball might hit this step: a box, how that box moves during the part of
// the step still to go, and the object to tell (nullptr for a wall).
struct Obstacle
{
    hitbox::Box box;
    hitbox::Vec2 move;
    hitbox::GameObject* object;
};

hitbox::Box movedBy(hitbox::Box box, hitbox::Vec2 offset)
{
    box.left += offset.x;
    box.top += offset.y;
    return box;
}

// A paddle as an obstacle, `timeDone` of the way through its planned move for this step.
Obstacle paddleObstacle(Paddle& paddle, float timeDone)
{
    const hitbox::Vec2 wholeMove = hitbox::toVec2(paddle.getPlannedMove());
    return {movedBy(hitbox::toBox(paddle.getCollisionBox()), wholeMove * timeDone),
            wholeMove * (1.f - timeDone), &paddle};
}

// The earliest hit along `ballMove` among the obstacles; `which` says whose it is.
hitbox::Hit firstHit(const hitbox::Box& ballBox, hitbox::Vec2 ballMove,
                     const Obstacle (&obstacles)[4], const Obstacle*& which)
{
    hitbox::Hit first;
    which = nullptr;
    for (const Obstacle& obstacle : obstacles)
    {
        const hitbox::Hit hit =
            hitbox::sweepBoxVsMovingBox(ballBox, ballMove, obstacle.box, obstacle.move);
        if (hit && (which == nullptr || hit.time < first.time))
        {
            first = hit;
            which = &obstacle;
        }
    }
    return first;
}
} // namespace

BallStep moveBall(Ball& ball, Paddle& left, Paddle& right, const Arena& arena, float dt)
{
    BallStep step;
    float timeLeft = 1.f; // the fraction of this step the ball has not moved through yet
    for (int attempt = 0; attempt < maxBouncesPerStep && timeLeft > 0.f; ++attempt)
    {
        // [slide:pong-swept-ball]
        // Sweep the rest of this step's move against everything; the earliest hit wins.
        const Obstacle obstacles[4] = {{hitbox::toBox(arena.topWall()), {}, nullptr},
                                       {hitbox::toBox(arena.bottomWall()), {}, nullptr},
                                       paddleObstacle(left, 1.f - timeLeft),
                                       paddleObstacle(right, 1.f - timeLeft)};
        const hitbox::Vec2 ballMove = hitbox::toVec2(ball.getVelocity()) * dt * timeLeft;
        const Obstacle* hitObstacle = nullptr;
        const hitbox::Hit hit =
            firstHit(hitbox::toBox(ball.getCollisionBox()), ballMove, obstacles, hitObstacle);
        if (hitObstacle == nullptr)
        {
            ball.move(hitbox::toSfml(ballMove)); // a clear path: the whole rest of the step
            return step;
        }
        ball.move(
            hitbox::toSfml(ballMove * hit.time)); // up to the contact: touching, not overlapping
        // [/slide]
        if (hit.startedInside)
        {
            // Already overlapping (rounding, or a paddle's end moved into it): push it out.
            ball.move(hitbox::toSfml(hit.normal * (hit.depth + separationSkin)));
            if (hitbox::dot(hitbox::toVec2(ball.getVelocity()), hit.normal) > 0.f)
                continue; // already moving away: the bounce has happened, not a new hit
        }
        // Tell the ball what it hit and how; it decides how to bounce (Ball.cpp).
        ball.setLastContact({true, hit.normal, hit.depth, hit.point});
        ball.collisionResponse(hitObstacle->object); // nullptr: a wall
        step.events.push_back(hitObstacle->object ? GameEvent::PaddleHit : GameEvent::WallHit);
        step.lastHit = hit;
        ++step.bounces;
        timeLeft *= 1.f - hit.time; // and sweep again with what is left of the step
    }
    return step;
}
