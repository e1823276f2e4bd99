// BroadPhase.cpp - your three searches. The exact tests and brute force are given, in
// Given.cpp: read bruteForcePairs first. Run every exact test through `exact.overlap`.
#include "BroadPhase.h"

#include "hitbox/geometry/Shapes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

// [slide:lab12-sort-and-sweep]
std::vector<Pair> sortAndSweepPairs(const std::vector<Box>& boxes, ExactBoxTests& exact)
{
    std::vector<Pair> pairs;
    // BEGIN TASK 1: sort and sweep
    // Visit the boxes by their left side. A box whose right side is at or before the new
    // box's left can never overlap it or any later box (they start further right): drop it
    // from the open list. Everything still open overlaps the new box on x; test those only.
    // (Ericson, Real-Time Collision Detection, 7.5.1, "sort and sweep".)
    std::vector<int> order(boxes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&boxes](int a, int b) { return boxes[a].left < boxes[b].left; });
    std::vector<int> open;
    for (const int index : order)
    {
        const Box& box = boxes[index];
        open.erase(std::remove_if(open.begin(), open.end(),
                                  [&](int other)
                                  { return hitbox::rightOf(boxes[other]) <= box.left; }),
                   open.end());
        for (const int other : open)
            if (exact.overlap(other, index))
                pairs.push_back({std::min(index, other), std::max(index, other)});
        open.push_back(index);
    }
    // STARTER TASK 1
    // (void)boxes;
    // (void)exact;
    // END TASK 1
    return pairs;
}
// [/slide]

// [slide:lab12-uniform-grid]
std::vector<Pair> gridPairs(const std::vector<Box>& boxes, float cellSize, ExactBoxTests& exact)
{
    std::vector<Pair> pairs;
    // BEGIN TASK 2: a uniform grid
    // 1. Fill: each box goes in every cell its box covers (floor, so negative coordinates
    //    land in negative cells). 2. List: within each cell, every pair of its boxes is a
    //    candidate; two boxes that share several cells meet in each, so collect the
    //    candidates, sort them and drop the repeats, then test each once.
    std::map<std::pair<int, int>, std::vector<int>> cells;
    for (int index = 0; index < static_cast<int>(boxes.size()); ++index)
    {
        const Box& box = boxes[index];
        const int firstColumn = static_cast<int>(std::floor(box.left / cellSize));
        const int lastColumn = static_cast<int>(std::floor(hitbox::rightOf(box) / cellSize));
        const int firstRow = static_cast<int>(std::floor(box.top / cellSize));
        const int lastRow = static_cast<int>(std::floor(hitbox::bottomOf(box) / cellSize));
        for (int column = firstColumn; column <= lastColumn; ++column)
            for (int row = firstRow; row <= lastRow; ++row)
                cells[{column, row}].push_back(index);
    }
    std::vector<Pair> candidates;
    for (const auto& cell : cells)
    {
        const std::vector<int>& inCell = cell.second;
        for (std::size_t a = 0; a < inCell.size(); ++a)
            for (std::size_t b = a + 1; b < inCell.size(); ++b)
                candidates.push_back(
                    {std::min(inCell[a], inCell[b]), std::max(inCell[a], inCell[b])});
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (const Pair& pair : candidates)
        if (exact.overlap(pair.first, pair.second))
            pairs.push_back(pair);
    // STARTER TASK 2
    // (void)boxes;
    // (void)cellSize;
    // (void)exact;
    // END TASK 2
    return pairs;
}
// [/slide]

// [slide:lab12-bound-first]
std::vector<Pair> ballPairsBoundFirst(const std::vector<Ball>& balls, ExactBallTests& exact)
{
    std::vector<Pair> pairs;
    // BEGIN TASK 3: cheap bound first, exact test second
    // Four comparisons of the balls' bounding boxes rule out most pairs; only the pairs
    // whose boxes overlap pay for the multiplications of the circle test. Boxes that only
    // touch cannot hold overlapping circles, so the strict box test loses nothing.
    const int count = static_cast<int>(balls.size());
    for (int first = 0; first < count; ++first)
        for (int second = first + 1; second < count; ++second)
        {
            const Ball& a = balls[first];
            const Ball& b = balls[second];
            const Box boundA{a.x - a.radius, a.y - a.radius, 2.f * a.radius, 2.f * a.radius};
            const Box boundB{b.x - b.radius, b.y - b.radius, 2.f * b.radius, 2.f * b.radius};
            if (overlaps(boundA, boundB) && exact.overlap(first, second))
                pairs.push_back({first, second});
        }
    // STARTER TASK 3
    // (void)balls;
    // (void)exact;
    // END TASK 3
    return pairs;
}
// [/slide]
