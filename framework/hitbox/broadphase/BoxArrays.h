// BoxArrays.h - the items' boxes as structure-of-arrays, ready for fast overlap tests.
//
// Every broadphase starts here. Loading does the edge-rule bookkeeping once per item instead
// of once per pair: negative sizes are flipped (normalised), and a box with NaN or infinite
// coordinates becomes an "empty" box (min = +inf, max = -inf) that fails every overlap test,
// so no method needs a special case for it. Separate arrays for minX, maxX, ... let the
// overlap loops read only the numbers they need, which the compiler turns into SIMD code.
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <cstdint>
#include <vector>

namespace hitbox
{

// [slide:layer-mask-filter]
// Game rules before geometry (aliens never test against aliens). Each object is on some
// layers (bits) and has a mask of the layers it wants to hit. Both must agree, so a pickup
// whose mask leaves out the pickup layer never pairs with another pickup, and a bullet whose
// mask leaves out its owner's layer never hits its owner.
[[nodiscard]] inline bool layersAllow(std::uint32_t layerA, std::uint32_t maskA,
                                      std::uint32_t layerB, std::uint32_t maskB)
{
    return (layerA & maskB) != 0 && (layerB & maskA) != 0;
}
// [/slide]

struct BoxArrays
{
    std::vector<float> minX, minY, maxX, maxY;
    std::vector<std::uint32_t> layer, mask;

    // Copies the items (reusing memory: no allocation once the vectors are big enough).
    void load(const std::vector<BroadphaseItem>& items);
    [[nodiscard]] std::size_t size() const { return minX.size(); }
    // False for the NaN / infinite boxes made empty by load().
    [[nodiscard]] bool isUsable(std::size_t i) const
    {
        return minX[i] <= maxX[i] && minY[i] <= maxY[i];
    }

    // The edge rule (spansOverlap, Shapes.h) on both axes; `&`: no branch to mispredict (on
    // unsigned values: clang warns about `&` between two bools, -Wbitwise-instead-of-logical).
    [[nodiscard]] bool overlap(std::size_t a, std::size_t b) const
    {
        return (static_cast<unsigned>(spansOverlap(minX[a], maxX[a], minX[b], maxX[b])) &
                static_cast<unsigned>(spansOverlap(minY[a], maxY[a], minY[b], maxY[b]))) != 0u;
    }
    [[nodiscard]] bool allowed(std::size_t a, std::size_t b) const
    {
        return layersAllow(layer[a], mask[a], layer[b], mask[b]);
    }
};

} // namespace hitbox
