#include "Ball.h"

#include "hitbox/geometry/Vec2.h"
#include "hitbox/objects/Collision.h"
#include "hitbox/sfml/Conversions.h"

#include <algorithm>
#include <cmath>

namespace
{
// Seconds a hit flash takes to fade.
constexpr float flashSeconds = 0.25f;
} // namespace

Ball::Ball(sf::Vector2f center, sf::Vector2f startVelocity, sf::Color color)
{
    setSize({2.f * ballRadius, 2.f * ballRadius});
    setOrigin({ballRadius, ballRadius});
    setPosition(center);
    setFillColor(color);
    setVelocity(startVelocity);
}

void Ball::update(float dt)
{
    move(velocity * dt);
    flash = std::max(0.f, flash - dt / flashSeconds);

    // [slide:lab02-bounce-walls]
    // BEGIN TASK 1: bounce off the window edges
    // The position is the centre, so the ball is out on the left when x < radius. Put it
    // back against the wall (touching is not colliding, so it does not stick) and send it
    // away from the wall: abs(), not a sign flip, which could send it back into the wall.
    const float radius = getRadius();
    sf::Vector2f center = getPosition();
    bool hitWall = false;
    if (center.x < radius || center.x > worldSize.x - radius)
    {
        velocity.x = center.x < radius ? std::abs(velocity.x) : -std::abs(velocity.x);
        center.x = std::clamp(center.x, radius, worldSize.x - radius);
        hitWall = true;
    }
    if (center.y < radius || center.y > worldSize.y - radius)
    {
        velocity.y = center.y < radius ? std::abs(velocity.y) : -std::abs(velocity.y);
        center.y = std::clamp(center.y, radius, worldSize.y - radius);
        hitWall = true;
    }
    setPosition(center);
    if (hitWall)
        collisionResponse(nullptr);
    // END TASK 1
    // [/slide]
}

void Ball::collisionResponse(hitbox::GameObject*)
{
    ++hitCount;
    flash = 1.f;
}

// [slide:lab02-elastic-response]
void bounceApart(Ball& first, Ball& second)
{
    // BEGIN TASK 3: bounce apart like billiard balls
    const hitbox::Contact contact = hitbox::Collision::getBoundingCircleContact(&first, &second);
    if (!contact.hit)
        return;
    // The maths is on hitbox::Vec2; a ball's position and velocity are SFML's sf::Vector2f:
    // hitbox::toVec2 and hitbox::toSfml (hitbox/sfml/Conversions.h) cross between the two.
    // 1. Separate: the normal points from `second` towards `first`; each ball moves half
    //    the overlap, so afterwards they just touch and the next step does not hit again.
    const hitbox::Vec2 normal = contact.normal;
    first.move(hitbox::toSfml(normal * (contact.depth / 2.f)));
    second.move(hitbox::toSfml(-normal * (contact.depth / 2.f)));
    // 2. Bounce: only the velocity along the normal changes. For equal masses an elastic
    //    collision swaps those parts, which is the same as each ball losing the closing
    //    speed along the normal and the other gaining it.
    const hitbox::Vec2 relative = hitbox::toVec2(first.getVelocity() - second.getVelocity());
    const float closing = hitbox::dot(relative, normal);
    if (closing >= 0.f)
        return; // already moving apart: leave them, or they would be pulled back together
    first.setVelocity(first.getVelocity() - hitbox::toSfml(normal * closing));
    second.setVelocity(second.getVelocity() + hitbox::toSfml(normal * closing));
    // STARTER TASK 3
    // (void)first;
    // (void)second;
    // END TASK 3
}
// [/slide]

void Ball::setWorldSize(sf::Vector2f size)
{
    worldSize = size;
}

float Ball::getRadius() const
{
    return getBoundingCircle().radius;
}

int Ball::getHitCount() const
{
    return hitCount;
}

float Ball::getFlash() const
{
    return flash;
}
