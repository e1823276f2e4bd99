// Broadphase.h - find every pair of boxes that overlap, without testing every pair.
//
// The cost of the obvious way: n objects need n(n-1)/2 tests, so 100 objects
// need 4,950 and 10,000 need about 50 million. A broadphase is the cheap first step of the
// plan "reduce the checks, quick test, thorough test, resolve": it looks only at
// the axis-aligned boxes and hands the pairs it finds to the exact shape tests.
//
// Every method answers exactly the same question, so tests compare them with brute force:
//   - two boxes pair only when they SHARE AREA (the edge rule in geometry/Overlap.h):
//     touching edges do not pair, a zero-size box pairs when strictly inside another,
//     negative sizes span backwards, NaN or infinite boxes never pair;
//   - game rules filter first: layers and masks (see below).
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace hitbox
{

// One collider as the broadphase sees it: its world box and which layers it is on / hits.
struct BroadphaseItem
{
    Box box;
    std::uint32_t layer = 1;
    std::uint32_t mask = 0xFFFFFFFF;
};

// A pair is considered only if (a.layer & b.mask) && (b.layer & a.mask).
struct Pair
{
    std::uint32_t first;
    std::uint32_t second;
}; // indices into items, first < second

enum class BroadphaseMethod
{
    BruteForce,
    SortAndSweep,
    Grid,
    Quadtree
};

// What the last findPairs did: how many box-box tests it ran, how many pairs it reported.
struct BroadphaseStats
{
    std::size_t pairsTested = 0;
    std::size_t pairsFound = 0;
};

// What a broadphase built in its last findPairs, as plain data: debug/BroadphaseDrawing.h
// draws it. Each method fills its own part; the others stay empty.
struct BroadphaseLayout
{
    // Grid: cell (column, row) is the square at gridOrigin + (column, row) * cellSize.
    Vec2 gridOrigin;
    float cellSize = 0.f;
    float averageSide = 0.f; // the boxes' average side in that frame (0: no usable box)
    int columns = 0;
    int rows = 0;
    std::vector<std::uint32_t> boxesPerCell; // row by row; empty when there is no grid
    // Quadtree: the region of every node.
    std::vector<Box> nodes;
    // Sort and sweep: each usable box's x range (left, right), in sweep order.
    std::vector<Vec2> sweepIntervals;
};

class Broadphase
{
public:
    virtual ~Broadphase() = default;
    // Every pair of items whose boxes share area (the framework's edge rule) and whose
    // layers/masks allow it, each once, sorted by (first, second). Reuses `pairs`' memory.
    virtual void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) = 0;
    [[nodiscard]] virtual const char* name() const = 0;
    [[nodiscard]] virtual BroadphaseStats stats() const = 0; // of the last findPairs
    // Grid cells / quadtree nodes / sweep axis of the last findPairs (brute force: none).
    [[nodiscard]] virtual BroadphaseLayout layout() const { return {}; }
};

// A broadphase with good defaults (the grid's cell size: the rule in GridCellRule.h).
[[nodiscard]] std::unique_ptr<Broadphase> makeBroadphase(BroadphaseMethod method);
// "BruteForce", "SortAndSweep", "Grid", "Quadtree".
[[nodiscard]] const char* toString(BroadphaseMethod method);

} // namespace hitbox
