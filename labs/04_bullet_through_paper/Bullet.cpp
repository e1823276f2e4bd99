#include "Bullet.h"

#include <algorithm>

namespace
{
const sf::Vector2f bulletSize{12.f, 6.f};
} // namespace

Bullet::Bullet(Lane whichLane, sf::Vector2f start, float bulletSpeed)
    : lane(whichLane), speed(bulletSpeed)
{
    setSize(bulletSize);
    setOrigin(bulletSize / 2.f);
    setPosition(start);
    setVelocity(speed, 0.f);
    setFillColor(sf::Color(250, 210, 90));
    trail.push_back(start);
    lastSweptArea = getCollisionBox();
}

Lane Bullet::getLane() const
{
    return lane;
}

float Bullet::getSpeed() const
{
    return speed;
}

bool Bullet::isFlying() const
{
    return flying;
}

bool Bullet::hitTheWall() const
{
    return stoppedByWall;
}

void Bullet::stopInTheWall()
{
    flying = false;
    stoppedByWall = true;
    setVelocity(0.f, 0.f);
}

void Bullet::flewAway()
{
    flying = false;
}

void Bullet::moveBy(sf::Vector2f step)
{
    const hitbox::Box before = hitbox::toBox(getCollisionBox());
    move(step);
    const hitbox::Box after = hitbox::toBox(getCollisionBox());
    const float left = std::min(before.left, after.left);
    const float top = std::min(before.top, after.top);
    const float right = std::max(before.left + before.width, after.left + after.width);
    const float bottom = std::max(before.top + before.height, after.top + after.height);
    lastSweptArea = sf::FloatRect({left, top}, {right - left, bottom - top});
    trail.push_back(getPosition());
}

const std::vector<sf::Vector2f>& Bullet::getTrail() const
{
    return trail;
}

sf::FloatRect Bullet::getLastSweptArea() const
{
    return lastSweptArea;
}

void Bullet::setCouldTunnel(bool couldTunnelNow)
{
    tunnelWarning = couldTunnelNow;
}

bool Bullet::couldTunnel() const
{
    return tunnelWarning;
}
