#include "Ball.h"

#include "Court.h"
#include "Paddle.h"

#include "hitbox/geometry/Sweep.h"
#include "hitbox/objects/Collision.h"

#include <algorithm>
#include <cmath>

Ball::Ball()
{
    setSize({ballSize, ballSize});
    setOrigin({ballSize / 2.f, ballSize / 2.f});
    setFillColor(sf::Color(250, 250, 250));
}

void Ball::placeAt(sf::Vector2f center, sf::Vector2f startVelocity)
{
    setPosition(center);
    setVelocity(startVelocity);
}

bool Ball::bounceOffWalls()
{
    // BEGIN TASK 2: bounce off the top and bottom walls
    // Past the top edge: back against it, moving down. abs(), not a sign flip, so a ball
    // already on its way back is never turned into the wall again. Touching is inside.
    const hitbox::Box box = hitbox::toBox(getCollisionBox());
    if (box.top < court.top)
    {
        move({0.f, court.top - box.top});
        velocity.y = std::abs(velocity.y);
        return true;
    }
    if (hitbox::bottomOf(box) > court.bottom)
    {
        move({0.f, court.bottom - hitbox::bottomOf(box)});
        velocity.y = -std::abs(velocity.y);
        return true;
    }
    return false;
    // STARTER TASK 2
    // return false; // the ball flies out through the top and the bottom
    // END TASK 2
}

void Ball::collisionResponse(hitbox::GameObject* other)
{
    if (other == nullptr)
        return;
    // BEGIN TASK 3: ball against paddle, the angle set by where it hit
    // Where it hit: -1 at the paddle's top end, 0 in the middle, +1 at the bottom end,
    // counting half the ball, so a ball that clips a corner counts as an end.
    const hitbox::Box paddle = hitbox::toBox(other->getCollisionBox());
    const hitbox::Vec2 paddleCenter = hitbox::centerOf(paddle);
    const float reach = paddle.height / 2.f + ballSize / 2.f;
    const float where = std::clamp((getPosition().y - paddleCenter.y) / reach, -1.f, 1.f);
    // Flat from the middle, maxBounceDegrees at the ends, back the way it came.
    const float angle = where * maxBounceDegrees * hitbox::pi / 180.f;
    const float away = getPosition().x < paddleCenter.x ? -1.f : 1.f;
    const float speed = std::hypot(velocity.x, velocity.y);
    velocity = {away * speed * std::cos(angle), speed * std::sin(angle)};
    // STARTER TASK 3
    // // not turned yet: the ball carries on into the paddle
    // END TASK 3
}

void moveBall(Ball& ball, Paddle& left, Paddle& right, float dt)
{
    // BEGIN TASK 5: the ball swept against the moving paddles
    // A discrete test only sees where the ball ends up: at 3000 px/s it moves 25 pixels a
    // step and jumps a 16-pixel paddle. A sweep looks at the whole move (Ericson, Real-Time
    // Collision Detection, 5.5.8; both paddle and ball move, so only the move of one
    // relative to the other matters). The earliest hit wins; then the rest of the step.
    // More hits than this in one step (a ball squeezed between a paddle's end and a wall)
    // and the rest of the step's move is dropped; the ball moves on next step.
    const int maxHitsPerStep = 4;
    float timeLeft = 1.f; // the part of this step the ball has not moved through yet
    for (int hits = 0; hits < maxHitsPerStep && timeLeft > 0.f; ++hits)
    {
        const hitbox::Vec2 ballMove = hitbox::toVec2(ball.getVelocity()) * dt * timeLeft;
        const hitbox::Box ballBox = hitbox::toBox(ball.getCollisionBox());
        hitbox::Hit first;
        Paddle* hitPaddle = nullptr;
        for (Paddle* paddle : {&left, &right})
        {
            // Where the paddle is now in its move, and the part of the move still to go.
            const hitbox::Vec2 paddleMove = hitbox::toVec2(paddle->getPlannedMove());
            hitbox::Box paddleBox = hitbox::toBox(paddle->getCollisionBox());
            paddleBox.top += paddleMove.y * (1.f - timeLeft);
            const hitbox::Hit hit =
                hitbox::sweepBoxVsMovingBox(ballBox, ballMove, paddleBox, paddleMove * timeLeft);
            if (hit && (hitPaddle == nullptr || hit.time < first.time))
            {
                first = hit;
                hitPaddle = paddle;
            }
        }
        if (hitPaddle == nullptr)
        {
            ball.move(hitbox::toSfml(ballMove)); // a clear path: the whole rest of the step
            return;
        }
        ball.move(hitbox::toSfml(ballMove * first.time)); // up to the paddle: touching
        if (first.startedInside)
            ball.move(hitbox::toSfml(first.normal * first.depth)); // pushed out, touching
        ball.collisionResponse(hitPaddle);
        timeLeft *= 1.f - first.time;
    }
    // STARTER TASK 5
    // // A discrete step: move, then "overlapping now?". A fast ball jumps a paddle.
    // ball.move(ball.getVelocity() * dt);
    // for (Paddle* paddle : {&left, &right})
    //     if (hitbox::Collision::checkBoundingBox(&ball, paddle))
    //         ball.collisionResponse(paddle);
    // END TASK 5
}
