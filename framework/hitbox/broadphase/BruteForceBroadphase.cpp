#include "hitbox/broadphase/BruteForceBroadphase.h"

namespace hitbox
{

void BruteForceBroadphase::findPairs(const std::vector<BroadphaseItem>& items,
                                     std::vector<Pair>& pairs)
{
    pairs.clear();
    boxes.load(items);
    std::size_t tested = 0;
    const std::uint32_t count = static_cast<std::uint32_t>(boxes.size());
    // [slide:pair-table]
    // Row `first`, column `second`: only the cells above the diagonal, so each pair is
    // tested once and nothing is tested against itself. n(n-1)/2 tests in all.
    for (std::uint32_t first = 0; first < count; ++first)
    {
        for (std::uint32_t second = first + 1; second < count; ++second)
        {
            if (!boxes.allowed(first, second))
                continue; // game rules say no: skip the box test
            ++tested;
            if (boxes.overlap(first, second))
                pairs.push_back({first, second});
        }
    }
    // [/slide]
    // Rows in order, columns in order: the pairs come out sorted by (first, second).
    lastStats.pairsTested = tested;
    lastStats.pairsFound = pairs.size();
}

} // namespace hitbox
