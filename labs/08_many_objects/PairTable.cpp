#include "PairTable.h"

#include "hitbox/geometry/Overlap.h"

void PairTable::reset(std::size_t newCount)
{
    count = newCount;
    cells.assign(count * count, Cell{});
    tests = 0;
    overlaps.clear();
}

void PairTable::record(std::uint32_t first, std::uint32_t second, bool overlapping)
{
    if (first >= count || second >= count)
        return; // not an object of this table: ignore rather than write past the end
    Cell& cell = cells[first * count + second];
    ++cell.tests;
    ++tests;
    if (overlapping)
    {
        cell.overlapping = true;
        overlaps.push_back({first, second});
    }
}

std::size_t PairTable::size() const
{
    return count;
}

int PairTable::timesTested(std::uint32_t row, std::uint32_t column) const
{
    return row < count && column < count ? cells[row * count + column].tests : 0;
}

bool PairTable::isOverlapping(std::uint32_t row, std::uint32_t column) const
{
    return row < count && column < count && cells[row * count + column].overlapping;
}

std::size_t PairTable::testsMade() const
{
    return tests;
}

const std::vector<hitbox::Pair>& PairTable::overlappingPairs() const
{
    return overlaps;
}

void testEveryPair(const std::vector<hitbox::BroadphaseItem>& items, PairTable& table,
                   PairRule mayCollide)
{
    table.reset(items.size());
    const auto count = static_cast<std::uint32_t>(items.size());
    // BEGIN TASK 1: test every pair once (only above the diagonal), obeying the rules
    // [slide:lab08-pair-loop]
    for (std::uint32_t i = 0; i < count; ++i)
    {
        // j starts after i: (2, 5) and (5, 2) are the same pair, and (i, i) is no pair.
        for (std::uint32_t j = i + 1; j < count; ++j)
        {
            // Game rules first: two ANDs are cheaper than any geometry.
            if (!mayCollide(items[i], items[j]))
                continue;
            table.record(i, j, hitbox::boxVsBox(items[i].box, items[j].box));
        }
    }
    // [/slide]
    // STARTER TASK 1
    // (void)count; // no pairs tested yet: the table stays empty
    // (void)mayCollide;
    // END TASK 1
}
