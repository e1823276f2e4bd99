#include "hitbox/broadphase/SortAndSweepBroadphase.h"

#include <algorithm>
#include <numeric>

namespace hitbox
{

void SortAndSweepBroadphase::sortByLeftEdge()
{
    const std::size_t count = order.size();
    // Insertion sort, but give up once it has moved more than a few steps per item: then the
    // order was far from right (objects teleported) and a full sort is cheaper.
    const std::size_t moveBudget = 8 * count + 64;
    std::size_t moves = 0;
    // [slide:sort-and-sweep-insertion]
    for (std::size_t i = 1; i < count && moves <= moveBudget; ++i)
    {
        const std::uint32_t item = order[i];
        const float key = boxes.minX[item];
        std::size_t j = i;
        // Nearly sorted input: this loop usually stops at once.
        while (j > 0 && boxes.minX[order[j - 1]] > key)
        {
            order[j] = order[j - 1];
            --j;
            ++moves;
        }
        order[j] = item;
    }
    // [/slide]
    if (moves > moveBudget)
    {
        std::sort(order.begin(), order.end(),
                  [this](std::uint32_t a, std::uint32_t b)
                  { return boxes.minX[a] < boxes.minX[b]; });
    }
}

void SortAndSweepBroadphase::findPairs(const std::vector<BroadphaseItem>& items,
                                       std::vector<Pair>& pairs)
{
    pairs.clear();
    boxes.load(items);
    const std::size_t count = boxes.size();
    if (order.size() != count)
    {
        // New or removed items: start from 0, 1, 2, ... (the sort below puts it right).
        order.resize(count);
        std::iota(order.begin(), order.end(), 0u);
    }
    // Unusable (NaN) boxes have minX = +inf: they sort to the end and never pair.
    sortByLeftEdge();

    std::size_t tested = 0;
    // [slide:sort-and-sweep]
    for (std::size_t i = 0; i < count; ++i)
    {
        const std::uint32_t a = order[i];
        const float right = boxes.maxX[a];
        // Every box after `a` starts at or right of a's left edge; once one starts at or
        // right of a's right edge, so do all the rest: stop the sweep there.
        for (std::size_t j = i + 1; j < count && boxes.minX[order[j]] < right; ++j)
        {
            const std::uint32_t b = order[j];
            if (!boxes.allowed(a, b))
                continue;
            ++tested;
            if (boxes.overlap(a, b))
                pairs.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    // [/slide]
    // The sweep finds pairs in x order; the interface promises (first, second) order.
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& p, const Pair& q)
              { return p.first != q.first ? p.first < q.first : p.second < q.second; });
    lastStats.pairsTested = tested;
    lastStats.pairsFound = pairs.size();
}

BroadphaseLayout SortAndSweepBroadphase::layout() const
{
    BroadphaseLayout result;
    for (const std::uint32_t item : order)
        if (boxes.isUsable(item))
            result.sweepIntervals.push_back({boxes.minX[item], boxes.maxX[item]});
    return result;
}

} // namespace hitbox
