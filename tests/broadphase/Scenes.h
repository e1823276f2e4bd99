// Scenes.h - seeded random scenes for the broadphase tests: the awkward cases on purpose
// (boxes on cell boundaries, touching edges, huge and negative coordinates, zero sizes,
// everything in one spot, NaN boxes, layers and masks).
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace scenes
{

enum class Kind
{
    Scattered,    // ordinary boxes in a 1200 x 675 world
    OnGridLines,  // coordinates and sizes multiples of 8: cell boundaries and touching edges
    BigAndSmall,  // a few boxes much bigger than any cell or node among small ones
    FarAndHuge,   // negative and very large coordinates and sizes
    ZeroSize,     // points and lines among boxes
    OneSpot,      // every box in the same place
    NegativeSize, // boxes that span backwards
    WithNaN,      // NaN and infinite coordinates among ordinary boxes
    Count
};

std::string describe(Kind kind);

// A scene of `kind` with about `count` boxes; layers and masks random when `useLayers`.
std::vector<hitbox::BroadphaseItem> make(Kind kind, std::size_t count, bool useLayers,
                                         std::mt19937& random);

// Moves every box a little (or, with `teleport`, some boxes very far), as a game frame does.
void move(std::vector<hitbox::BroadphaseItem>& items, bool teleport, std::mt19937& random);

// The answer every broadphase must give, written straight from the definition: every pair
// i < j that the layers allow and hitbox::boxVsBox says shares area.
std::vector<hitbox::Pair> referencePairs(const std::vector<hitbox::BroadphaseItem>& items);

} // namespace scenes
