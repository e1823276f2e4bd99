#include "Ball.h"

#include <algorithm>
#include <cmath>

namespace
{
const float degreesToRadians = hitbox::pi / 180.f;

float lengthOf(sf::Vector2f v)
{
    return std::sqrt(v.x * v.x + v.y * v.y);
}
} // namespace

Ball::Ball(const BallSettings& ballSettings) : settings(ballSettings)
{
    setSize({settings.size, settings.size});
    // Origin in the middle, and the collision box measured from it (GameObject.h).
    setOrigin({settings.size / 2.f, settings.size / 2.f});
    setCollisionBox(-settings.size / 2.f, -settings.size / 2.f, settings.size, settings.size);
    setFillColor(sf::Color(245, 245, 245));
}

void Ball::placeAt(sf::Vector2f center)
{
    setPosition(center);
    setVelocity(0.f, 0.f);
    paddleHits = 0;
    lastContact = {};
}

void Ball::serve(int direction, float degrees)
{
    const float angle = degrees * degreesToRadians;
    setVelocity(static_cast<float>(direction) * settings.serveSpeed * std::cos(angle),
                settings.serveSpeed * std::sin(angle));
}

bool Ball::isMoving() const
{
    return velocity.x != 0.f || velocity.y != 0.f;
}

float Ball::getSpeed() const
{
    return lengthOf(velocity);
}

int Ball::getPaddleHits() const
{
    return paddleHits;
}

void Ball::setLastContact(const hitbox::Contact& contact)
{
    lastContact = contact;
}

const hitbox::Contact& Ball::getLastContact() const
{
    return lastContact;
}

const BallSettings& Ball::getSettings() const
{
    return settings;
}

// [slide:pong-collision-response]
void Ball::collisionResponse(hitbox::GameObject* other)
{
    // The physics stored the contact first; its normal points out of what we hit, towards
    // the ball (Shapes.h). A wall is the world, so it arrives as nullptr (GameObject.h).
    if (other == nullptr)
        bounceOffWall();
    else if (lastContact.normal.x != 0.f)
        bounceOffPaddleFace(*other); // its front: a proper return
    else
        bounceOffPaddleEnd(*other); // an end: knocked away, in play
}

void Ball::bounceOffWall()
{
    // Reflect: remove the part of the velocity going into the wall, twice. Only when moving
    // into it, so a ball resting against the wall is never turned back into it.
    const sf::Vector2f normal = hitbox::toSfml(lastContact.normal);
    const float into = hitbox::dot(hitbox::toVec2(velocity), lastContact.normal);
    if (into < 0.f)
        velocity -= 2.f * into * normal;
}
// [/slide]

// [slide:pong-paddle-angle]
void Ball::bounceOffPaddleFace(const hitbox::GameObject& paddle)
{
    // Where did it hit? -1 at the paddle's top end, 0 in the middle, +1 at the bottom end.
    // Counting half the ball too, so a ball that only clips the corner still counts as +-1.
    const hitbox::Box paddleBox = hitbox::toBox(paddle.getCollisionBox());
    const float reach = paddleBox.height / 2.f + settings.size / 2.f;
    const float offset = (getPosition().y - hitbox::centerOf(paddleBox).y) / reach;
    const float hitPosition = std::max(-1.f, std::min(1.f, offset));

    // Middle: flat. Ends: steep, but never more than maxBounceDegrees (never vertical).
    const float angle = hitPosition * settings.maxBounceDegrees * degreesToRadians;
    const float speed = std::min(getSpeed() + settings.speedUpPerHit, settings.maxSpeed);
    const float away = lastContact.normal.x > 0.f ? 1.f : -1.f; // back the way it came
    velocity = {away * speed * std::cos(angle), speed * std::sin(angle)};
    ++paddleHits;
}
// [/slide]

void Ball::bounceOffPaddleEnd(const hitbox::GameObject& paddle)
{
    // Turn round vertically, and leave faster than the paddle is moving, so the paddle that
    // is chasing the ball does not catch it again in the next step.
    const float away = lastContact.normal.y > 0.f ? 1.f : -1.f;
    const float paddleSpeed = std::abs(paddle.getVelocity().y);
    velocity.y = away * std::max(std::abs(velocity.y), paddleSpeed + 60.f);
}
