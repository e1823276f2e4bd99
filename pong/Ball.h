// Ball.h - the Pong ball: a small square GameObject that speeds up and changes angle on
// every paddle hit.
//
// The ball does not move itself: BallPhysics.cpp sweeps it along its path each step and,
// at every hit, records the contact (setLastContact) and calls collisionResponse(), exactly
// as a student's object would be told "you hit something".
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/objects/GameObject.h"

// The numbers students tune, in one place. Speeds in pixels per second.
struct BallSettings
{
    float size = 14.f;
    float serveSpeed = 460.f;
    float speedUpPerHit = 40.f; // added on each paddle hit ...
    float maxSpeed = 1400.f;    // ... up to this cap
    // The steepest outgoing angle from the horizontal, at the very end of a paddle. Below 90
    // degrees, so the ball never goes straight up and down and every rally reaches a goal.
    float maxBounceDegrees = 60.f;
};

class Ball : public hitbox::GameObject
{
public:
    explicit Ball(const BallSettings& settings = {});

    // Put the ball at `center`, still (waiting to be served).
    void placeAt(sf::Vector2f center);
    // Start moving at the serve speed: `direction` is -1 (to the left) or +1 (to the right),
    // `degrees` the angle from the horizontal (positive = downwards).
    void serve(int direction, float degrees);
    bool isMoving() const;
    float getSpeed() const;
    int getPaddleHits() const; // paddle hits since the last serve

    // The contact the physics found just before calling collisionResponse().
    void setLastContact(const hitbox::Contact& contact);
    const hitbox::Contact& getLastContact() const;

    // other == nullptr: a wall. Otherwise a paddle.
    void collisionResponse(hitbox::GameObject* other) override;

    const BallSettings& getSettings() const;

private:
    void bounceOffWall();
    void bounceOffPaddleFace(const hitbox::GameObject& paddle);
    void bounceOffPaddleEnd(const hitbox::GameObject& paddle);

    BallSettings settings;
    hitbox::Contact lastContact;
    int paddleHits = 0;
};
