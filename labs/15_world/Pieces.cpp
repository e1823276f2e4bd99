#include "Pieces.h"

#include "hitbox/app/Level.h"
#include "hitbox/sfml/Conversions.h"

#include <algorithm>
#include <cmath>

Piece::Piece(Kind pieceKind) : kind(pieceKind) {}

Kind Piece::getKind() const
{
    return kind;
}

Kind kindOf(const hitbox::GameObject& object)
{
    return static_cast<const Piece&>(object).getKind();
}

namespace
{
// A square of `size` pixels centred on `center`.
void makeSquare(hitbox::GameObject& object, sf::Vector2f center, float size)
{
    object.setSize({size, size});
    object.setOrigin({size / 2.f, size / 2.f});
    object.setPosition(center);
}

// Keeps a centred square of `size` inside `world`; returns which way it was pushed back
// (-1, 0 or +1 on each axis).
sf::Vector2f keepInside(hitbox::GameObject& object, float size, sf::Vector2f world)
{
    const float half = size / 2.f;
    const sf::Vector2f center = object.getPosition();
    const sf::Vector2f inside{std::clamp(center.x, half, world.x - half),
                              std::clamp(center.y, half, world.y - half)};
    object.setPosition(inside);
    return {inside.x > center.x ? 1.f : (inside.x < center.x ? -1.f : 0.f),
            inside.y > center.y ? 1.f : (inside.y < center.y ? -1.f : 0.f)};
}
} // namespace

Player::Player(sf::Vector2f center) : Piece(Kind::Player), worldSize(hitbox::defaultWorldSize)
{
    makeSquare(*this, center, playerSize);
    setFillColor({90, 160, 240});
}

void Player::update(float dt)
{
    move(velocity * dt);
    keepInside(*this, playerSize, worldSize);
    blinkLeft = std::max(0.f, blinkLeft - dt);
}

void Player::setWorldSize(sf::Vector2f size)
{
    worldSize = size;
}

void Player::collisionResponse(hitbox::GameObject* other)
{
    if (other == nullptr || kindOf(*other) != Kind::Enemy)
        return;
    ++hurtCount;
    blinkLeft = blinkSeconds;
}

bool Player::isBlinking() const
{
    return blinkLeft > 0.f;
}

float Player::getBlinkLeft() const
{
    return blinkLeft;
}

int Player::getHurtCount() const
{
    return hurtCount;
}

Coin::Coin(sf::Vector2f center) : Piece(Kind::Coin)
{
    makeSquare(*this, center, 2.f * coinRadius); // the bounding circle is the inscribed one
    setFillColor({250, 205, 60});
}

bool Coin::isCollected() const
{
    return collected;
}

Enemy::Enemy(sf::Vector2f center, sf::Vector2f startVelocity)
    : Piece(Kind::Enemy), worldSize(hitbox::defaultWorldSize)
{
    makeSquare(*this, center, enemySize);
    setFillColor({220, 75, 70});
    setVelocity(startVelocity);
}

void Enemy::update(float dt)
{
    move(velocity * dt);
    const sf::Vector2f pushed = keepInside(*this, enemySize, worldSize);
    // Away from the wall it was pushed back from (abs, not a sign flip: it may still be there).
    if (pushed.x != 0.f)
        velocity.x = pushed.x * std::abs(velocity.x);
    if (pushed.y != 0.f)
        velocity.y = pushed.y * std::abs(velocity.y);
}

void Enemy::setWorldSize(sf::Vector2f size)
{
    worldSize = size;
}

void Enemy::collisionResponse(hitbox::GameObject* other)
{
    if (other == nullptr || kindOf(*other) != Kind::Enemy)
        return;
    ++bumpCount;
    // Head straight away from the other enemy, at the same speed.
    const sf::Vector2f away = getPosition() - other->getPosition();
    const float distance = hitbox::length(hitbox::toVec2(away));
    const float speed = hitbox::length(hitbox::toVec2(velocity));
    if (distance > 0.f)
        velocity = away * (speed / distance);
}

int Enemy::getBumpCount() const
{
    return bumpCount;
}
