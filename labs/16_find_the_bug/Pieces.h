// Pieces.h - the things in lab 16's depot: crates on two belts, a pressure plate, the gate's
// doorway, the drop zone and the gatekeeper.
//
// Each is a GameObject whose position is its top-left corner. A Piece knows its Kind, so a
// response or an event can ask what it met without a cast.
#pragma once

#include "hitbox/objects/GameObject.h"

#include <cstdint>

// The numbers to play with.
constexpr float crateSize = 40.f;   // pixels, each crate's square
constexpr float crateSpeed = 120.f; // pixels per second along the belts
constexpr float guardSize = 40.f;   // pixels, the gatekeeper's square
constexpr float guardSpeed = 120.f; // pixels per second (arrow keys)

enum class Kind
{
    Crate,
    Plate,
    Gateway,
    DropZone,
    Guard
};

// One bit per group: crates meet the plate, the gateway and the drop zone; the gatekeeper
// meets the gateway.
namespace layer
{
constexpr std::uint32_t crate = 1u << 0;
constexpr std::uint32_t zone = 1u << 1;
constexpr std::uint32_t guard = 1u << 2;
} // namespace layer

class Piece : public hitbox::GameObject
{
public:
    // A box of `size` with its top-left corner at `topLeft`.
    Piece(Kind kind, sf::Vector2f topLeft, sf::Vector2f size);
    [[nodiscard]] Kind getKind() const;

private:
    Kind kind;
};

// What `object` is (every object in this lab is a Piece).
[[nodiscard]] Kind kindOf(const hitbox::GameObject& object);

class Crate : public Piece
{
public:
    explicit Crate(sf::Vector2f topLeft);
    // Entering the drop zone delivers the crate (the level then takes it away: task 3).
    void onCollisionEnter(const hitbox::CollisionEvent& event) override;
    [[nodiscard]] bool isDelivered() const;

private:
    bool delivered = false;
};

// Task 1 (Bugs.cpp): pressed while anything stands on it; the gate opens while it is pressed.
class PressurePlate : public Piece
{
public:
    PressurePlate(sf::Vector2f topLeft, sf::Vector2f size);
    void collisionResponse(hitbox::GameObject* other) override;
    void onCollisionEnter(const hitbox::CollisionEvent& event) override;
    void onCollisionExit(const hitbox::CollisionEvent& event) override;
    [[nodiscard]] bool isPressed() const;

protected:
    // Yours to use in task 1 (protected rather than private: a compiler may warn about a
    // private field your answer does not use).
    bool alreadyPressed = false;
    int standingOn = 0;
};
