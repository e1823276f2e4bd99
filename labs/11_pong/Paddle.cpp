#include "Paddle.h"

#include "Court.h"

#include <algorithm>

Paddle::Paddle(float centerX)
{
    setSize({paddleWidth, paddleHeight});
    setOrigin({paddleWidth / 2.f, paddleHeight / 2.f}); // the position is the centre
    setPosition({centerX, (court.top + court.bottom) / 2.f});
    setFillColor(sf::Color(230, 230, 235));
}

sf::Vector2f Paddle::moveWithinCourt(float direction, float dt) const
{
    // BEGIN TASK 1: move the paddles within the court
    // The furthest it may go each way this step: up until its top touches the court's top,
    // down until its bottom touches the bottom. Clamp the wanted move between the two.
    const hitbox::Box box = hitbox::toBox(getCollisionBox());
    const float furthestUp = court.top - box.top;                    // zero or negative
    const float furthestDown = court.bottom - hitbox::bottomOf(box); // zero or positive
    const float wanted = std::clamp(direction, -1.f, 1.f) * paddleSpeed * dt;
    return {0.f, std::max(furthestUp, std::min(furthestDown, wanted))};
    // STARTER TASK 1
    // return {0.f, direction * paddleSpeed * dt}; // leaves the court
    // END TASK 1
}

void Paddle::setPlannedMove(sf::Vector2f move)
{
    plannedMove = move;
}

sf::Vector2f Paddle::getPlannedMove() const
{
    return plannedMove;
}

void Paddle::finishMove()
{
    move(plannedMove);
    plannedMove = {};
}

float computerDirection(const Ball& ball, const Paddle& paddle, float dt)
{
    // BEGIN TASK 6: a computer opponent
    // It watches the ball as a person would. Coming towards it: head for the ball's height.
    // Going away: drift back to the middle, ready for anything.
    // Coming: moving sideways towards the paddle's side of the ball. With no sideways speed,
    // or level with the paddle, the product is 0: not coming (the sheet's rule).
    const sf::Vector2f ballAt = ball.getPosition();
    const bool coming = ball.getVelocity().x * (paddle.getPosition().x - ballAt.x) > 0.f;
    const float targetY = coming ? ballAt.y : (court.top + court.bottom) / 2.f;
    if (dt <= 0.f)
        return 0.f;
    // Just as far as it needs this step (so it does not shake about the target), and never
    // faster than computerTopSpeed: a steep shot far from it gets past, so it can be beaten.
    const float stepsAway = (targetY - paddle.getPosition().y) / (paddleSpeed * dt);
    return std::clamp(stepsAway, -computerTopSpeed, computerTopSpeed);
    // STARTER TASK 6
    // (void)ball;
    // (void)paddle;
    // (void)dt;
    // return 0.f; // the computer's paddle stands still
    // END TASK 6
}
