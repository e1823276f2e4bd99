// Rules.h - what you write in lab 15 (Rules.cpp): which objects may meet, what a coin does
// when the player touches it, and one game rule.
#pragma once

#include "Pieces.h"

#include "hitbox/objects/World.h"

#include <cstdint>
#include <memory>
#include <vector>

// The layers an object is on, and the layers it collides with (hitbox::World::add).
struct Layers
{
    std::uint32_t layer = 1;
    std::uint32_t mask = 0xFFFFFFFF;
};

// Task 1: the layer and mask of each kind of object.
Layers layersFor(Kind kind);

// True when a World would ever test objects with these layers against each other: each
// one's layer is in the other's mask (the rule World applies, written out for the tests).
inline bool mayEverMeet(const Layers& first, const Layers& second)
{
    return (first.layer & second.mask) != 0 && (second.layer & first.mask) != 0;
}

// Task 2: takes every collected coin out of `world`, then destroys it; returns how many.
int removeCollectedCoins(hitbox::World& world, std::vector<std::unique_ptr<Coin>>& coins);

// Task 3: the game rule (World::setRule): false for a pair that must not be tested now.
bool mayMeetNow(const hitbox::GameObject& first, const hitbox::GameObject& second);
