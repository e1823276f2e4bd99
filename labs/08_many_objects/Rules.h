// Rules.h - game rules as layers and masks (as Box2D's collision filtering does with
// category and mask bits): pairs the game never cares about are never tested.
//
// Every ball is on one layer (one bit) and has a mask (the layers it wants to touch).
// A pair is worth testing only when each one's layer is in the other's mask. The check
// costs two ANDs, so it runs before any geometry.
#pragma once

#include "Ball.h"

#include <cstdint>

// One bit per layer. Ships and bullets have one layer per owner, so a bullet can ignore
// the ship that fired it and still hit the other one.
namespace layer
{
constexpr std::uint32_t plain = 1u << 0;
constexpr std::uint32_t ship0 = 1u << 1;
constexpr std::uint32_t ship1 = 1u << 2;
constexpr std::uint32_t bullet0 = 1u << 3;
constexpr std::uint32_t bullet1 = 1u << 4;
constexpr std::uint32_t pickup = 1u << 5;
} // namespace layer

struct CollisionFilter
{
    std::uint32_t layer = 1;
    std::uint32_t mask = 0xFFFFFFFF;
};

// The layer and mask a ball of `kind` gets. The rules of the layers scene:
//   bullets never hit the ship that fired them, nor other bullets;
//   pickups ignore each other (a pile of them stays a pile);
//   everything else collides.
CollisionFilter filterFor(BallKind kind, int owner);

// True when a and b may collide under their layers and masks (both must agree).
bool layersMayCollide(const hitbox::BroadphaseItem& a, const hitbox::BroadphaseItem& b);
