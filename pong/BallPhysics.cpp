#include "BallPhysics.h"

namespace
{
// One thing the ball might hit this step: a box, how that box moves during the part of
// the step still to go, and the object to tell (nullptr for a wall).
struct Obstacle
{
    sf::FloatRect box;
    sf::Vector2f move;
    GameObject* object;
};

sf::FloatRect movedBy(sf::FloatRect box, sf::Vector2f offset)
{
    box.left += offset.x;
    box.top += offset.y;
    return box;
}
} // namespace

// [slide:pong-swept-ball]
BallStep moveBall(Ball& ball, Paddle& left, Paddle& right, const Arena& arena, float dt)
{
    BallStep step;
    float timeLeft = 1.f; // the fraction of this step the ball has not moved through yet
    while (timeLeft > 0.f && step.bounces < maxBouncesPerStep)
    {
        // Where everything is now, and how it moves in the rest of the step.
        const float timeDone = 1.f - timeLeft;
        const Obstacle obstacles[] = {
            {arena.topWall(), {}, nullptr},
            {arena.bottomWall(), {}, nullptr},
            {movedBy(left.getCollisionBox(), left.getPlannedMove() * timeDone),
             left.getPlannedMove() * timeLeft, &left},
            {movedBy(right.getCollisionBox(), right.getPlannedMove() * timeDone),
             right.getPlannedMove() * timeLeft, &right}};
        const sf::Vector2f ballMove = ball.getVelocity() * dt * timeLeft;

        // The earliest hit along the whole move wins.
        hitbox::Hit first;
        const Obstacle* hitObstacle = nullptr;
        for (const Obstacle& obstacle : obstacles)
        {
            const hitbox::Hit hit = hitbox::sweepBoxVsMovingBox(ball.getCollisionBox(), ballMove,
                                                                obstacle.box, obstacle.move);
            if (hit && (hitObstacle == nullptr || hit.time < first.time))
            {
                first = hit;
                hitObstacle = &obstacle;
            }
        }
        if (hitObstacle == nullptr)
        {
            ball.move(ballMove); // a clear path: the whole rest of the step
            break;
        }

        // Move up to the contact (or out, if it started inside), then bounce.
        ball.move(ballMove * first.time);
        if (first.startedInside)
            ball.move(first.normal * first.depth);
        ball.setLastContact({true, first.normal, first.depth, first.point});
        ball.collisionResponse(hitObstacle->object);
        step.events.push_back(hitObstacle->object ? GameEvent::PaddleHit : GameEvent::WallHit);
        step.lastHit = first;
        ++step.bounces;
        timeLeft *= 1.f - first.time;
    }
    return step;
}
// [/slide]
