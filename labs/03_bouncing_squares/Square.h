// Square.h - a crate picture that flies in a straight line and bounces off the world's edges
// (Square::update) and off other crates (bounceApart).
//
// The picture (the sprite) is spriteSize pixels wide, but like most sprites it has a
// see-through margin: the crate itself, the part a player sees, is only crateSize wide, in
// the middle. The origin is the centre of the picture, so getPosition() is the centre.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/objects/GameObject.h"

// The numbers to play with.
constexpr float spriteSize = 100.f;  // the whole picture, margin included (pixels)
constexpr float crateSize = 64.f;    // the solid crate in the middle of the picture
constexpr float squareSpeed = 220.f; // pixels per second, every square's speed at the start

class Square : public hitbox::GameObject
{
public:
    Square(sf::Vector2f center, sf::Vector2f startVelocity, sf::Color color);

    // Moves the square, then keeps its collision box inside the world.
    void update(float dt) override;
    // Something hit the square: another square, or a wall when `other` is nullptr.
    void collisionResponse(hitbox::GameObject* other) override;

    void setWorldSize(sf::Vector2f size);
    // How many hits collisionResponse has been told about (walls and squares).
    int getHitCount() const;
    // 1 just after a hit, fading to 0: render() flashes the crate with it.
    float getFlash() const;

private:
    sf::Vector2f worldSize = hitbox::defaultWorldSize;
    int hitCount = 0;
    float flash = 0.f;
};

// If the two squares' collision boxes overlap (touching is not overlapping), tells both,
// moves them apart until they just touch and swaps their velocities along the normal.
void bounceApart(Square& first, Square& second);
