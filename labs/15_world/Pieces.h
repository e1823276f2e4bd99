// Pieces.h - the three kinds of object in lab 15: the player, coins and enemies.
//
// Each is a GameObject whose origin is its centre. A Piece knows its Kind, so a collision
// response (or a game rule) can ask what it hit without a cast.
#pragma once

#include "hitbox/objects/GameObject.h"

#include <cstdint>

// The numbers to play with.
constexpr float playerSize = 40.f;      // pixels, the player's square
constexpr float playerSpeed = 300.f;    // pixels per second
constexpr float coinRadius = 12.f;      // pixels
constexpr float enemySize = 36.f;       // pixels, each enemy's square
constexpr float enemySpeed = 110.f;     // pixels per second
constexpr float blinkSeconds = 1.5f;    // how long a hurt player blinks
constexpr float enemyTurnSeconds = 2.f; // an enemy picks a new direction this often

enum class Kind
{
    Player,
    Coin,
    Enemy
};

// One bit per kind: the layers a World sorts objects into (Rules.cpp, task 1).
namespace layer
{
constexpr std::uint32_t player = 1u << 0;
constexpr std::uint32_t coin = 1u << 1;
constexpr std::uint32_t enemy = 1u << 2;
} // namespace layer

class Piece : public hitbox::GameObject
{
public:
    explicit Piece(Kind kind);
    Kind getKind() const;

private:
    Kind kind;
};

// What `object` is (every object in this lab is a Piece).
Kind kindOf(const hitbox::GameObject& object);

class Player : public Piece
{
public:
    explicit Player(sf::Vector2f center);

    // Moves by velocity, kept inside `worldSize`; the blink runs down.
    void update(float dt) override;
    void setWorldSize(sf::Vector2f size);
    // An enemy hurts the player every time it is told about one, and starts it blinking.
    // (Task 3's game rule is what stops a blinking player being hurt again.)
    void collisionResponse(hitbox::GameObject* other) override;

    bool isBlinking() const;
    float getBlinkLeft() const; // seconds
    int getHurtCount() const;

private:
    sf::Vector2f worldSize;
    float blinkLeft = 0.f;
    int hurtCount = 0;
};

class Coin : public Piece
{
public:
    explicit Coin(sf::Vector2f center);
    // Task 2 (Rules.cpp): touched by the player, the coin is collected.
    void collisionResponse(hitbox::GameObject* other) override;
    bool isCollected() const;

private:
    bool collected = false;
};

class Enemy : public Piece
{
public:
    Enemy(sf::Vector2f center, sf::Vector2f startVelocity);

    // Moves, bounces off the edges of `worldSize`.
    void update(float dt) override;
    void setWorldSize(sf::Vector2f size);
    // Another enemy: head away from it (they bump). Anything else: keep going.
    void collisionResponse(hitbox::GameObject* other) override;
    int getBumpCount() const;

private:
    sf::Vector2f worldSize;
    int bumpCount = 0;
};
