// PairTable.h - the n x n table of every pair of balls: row i, column j is the pair (i, j). Testing
// every pair once means filling the cells above the diagonal, n(n-1)/2 of them: 45 for 10 balls,
// 4,950 for 100, 49,995,000 for 10,000. That growth (O(n^2)) is why broadphases exist.
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <cstddef>
#include <cstdint>
#include <vector>

class PairTable
{
public:
    // Forget everything; make an empty table for `count` objects.
    void reset(std::size_t count);
    // The pair (first, second) was tested; `overlapping` is what the test said.
    void record(std::uint32_t first, std::uint32_t second, bool overlapping);

    std::size_t size() const;
    // How many times the pair (row, column) was recorded (should be 0 or 1).
    int timesTested(std::uint32_t row, std::uint32_t column) const;
    bool isOverlapping(std::uint32_t row, std::uint32_t column) const;
    std::size_t testsMade() const;
    // The overlapping pairs in the order they were recorded.
    const std::vector<hitbox::Pair>& overlappingPairs() const;

private:
    struct Cell
    {
        int tests = 0;
        bool overlapping = false;
    };
    std::size_t count = 0;
    std::vector<Cell> cells; // row-major, count x count
    std::size_t tests = 0;
    std::vector<hitbox::Pair> overlaps;
};

// A game rule: true when the two items may ever collide (the lab's: layersMayCollide).
using PairRule = bool (*)(const hitbox::BroadphaseItem& a, const hitbox::BroadphaseItem& b);

// The brute-force loop: test every pair of items once, skipping pairs the game rule
// `mayCollide` rules out, and record each test in `table`. Boxes overlap by hitbox::boxVsBox
// (sharing area; touching edges do not count). The rule is a parameter so the loop can be
// checked with any rule, whatever state task 3's rules are in.
void testEveryPair(const std::vector<hitbox::BroadphaseItem>& items, PairTable& table,
                   PairRule mayCollide);
