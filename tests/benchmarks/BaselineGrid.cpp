#include "BaselineGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bench
{
using hitbox::spansOverlap;

namespace
{

// Never more than this many cells per item, so empty space (or one far-away object) cannot
// make the grid huge: the cell size grows instead.
constexpr double kMaxCellsPerItem = 4.0;
// Far below anything a game uses, and 1 / this is still a float.
constexpr double kSmallestCellSize = 1e-30;
// The cell rule of the time (the framework's kGridCellPerAverageSide then), kept here so a
// change to today's rule does not change the baseline.
constexpr double kBaselineCellPerAverageSide = 3.0;
double gridCellSizeFor(double averageSide)
{
    return kBaselineCellPerAverageSide * averageSide;
}

// Branch-free select: `oneOrZero ? ifOne : ifZero` with bit masks. Where g++ 12 compiles the
// `?:` to a jump, the CPU has to guess it, and a wrong guess costs more than these three steps.
inline std::uint32_t selectWithoutBranch(std::uint32_t oneOrZero, std::uint32_t ifOne,
                                         std::uint32_t ifZero)
{
    const std::uint32_t keep = 0u - oneOrZero; // unsigned wrap-around: 0 - 1 is all ones
    return (ifOne & keep) | (ifZero & ~keep);
}

} // namespace

BaselineGrid::BaselineGrid(float cellSize) : fixedCellSize(cellSize) {}

void BaselineGrid::chooseGrid()
{
    const std::size_t count = boxes.size();
    // A box edge can be +-infinity when left + width overflowed; the grid only needs
    // finite numbers (boxes beyond it land in its edge cells).
    const float largest = std::numeric_limits<float>::max();
    auto finite = [largest](float value) { return std::clamp(value, -largest, largest); };
    float left = 0.f, top = 0.f, right = 0.f, bottom = 0.f;
    double sideSum = 0.0;
    std::size_t usable = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
        if (!boxes.isUsable(i))
            continue;
        const float minX = finite(boxes.minX[i]), maxX = finite(boxes.maxX[i]);
        const float minY = finite(boxes.minY[i]), maxY = finite(boxes.maxY[i]);
        if (usable == 0)
        {
            left = minX;
            top = minY;
            right = maxX;
            bottom = maxY;
        }
        left = std::min(left, minX);
        top = std::min(top, minY);
        right = std::max(right, maxX);
        bottom = std::max(bottom, maxY);
        sideSum += 0.5 * ((double(maxX) - minX) + (double(maxY) - minY));
        ++usable;
    }
    originX = left;
    originY = top;
    // Work in double: the extent of boxes at +-1e38 does not fit in a float.
    const double width = double(right) - left;
    const double height = double(bottom) - top;
    double cell = fixedCellSize > 0.f ? fixedCellSize
                  : usable > 0        ? gridCellSizeFor(sideSum / double(usable))
                                      : 1.0;
    if (!(cell > 0.0) || !std::isfinite(cell))
        cell = std::max({width, height, 1.0}); // every box has zero size: one big cell
    // Cells are found by multiplying by 1 / cell size. For cells below about 1e-38 that is
    // infinity in float, and 0 * infinity is NaN, which has no cell: never go that small.
    cell = std::max(cell, kSmallestCellSize);
    // Never more than a few cells per box: a lone box far away (or a tiny cell size) would
    // otherwise make a grid of mostly empty cells. Grow the cells instead.
    const double maxCells = kMaxCellsPerItem * double(count) + 16.0;
    double cellsX = std::max(1.0, std::ceil(width / cell));
    double cellsY = std::max(1.0, std::ceil(height / cell));
    if (cellsX * cellsY > maxCells)
    {
        cell *= std::sqrt(cellsX * cellsY / maxCells);
        cellsX = std::max(1.0, std::ceil(width / cell));
        cellsY = std::max(1.0, std::ceil(height / cell));
    }
    columns = static_cast<int>(std::min(cellsX, maxCells));
    rows = static_cast<int>(std::min(cellsY, std::floor(maxCells / columns) + 1.0));
    usedCellSize = static_cast<float>(std::min(cell, double(largest)));
}

void BaselineGrid::assignCells()
{
    const std::size_t count = boxes.size();
    cellRanges.resize(count);
    const float scale = 1.f / usedCellSize;
    const float lastColumn = static_cast<float>(columns - 1);
    const float lastRow = static_cast<float>(rows - 1);
    // Which cells does a box cover? Divide by the cell size and round down. Clamping to the
    // grid keeps the answer monotonic (a box further right never gets a smaller column), so
    // two overlapping boxes always share a cell, even boxes outside the grid.
    auto column = [&](float x)
    { return static_cast<int>(std::clamp((x - originX) * scale, 0.f, lastColumn)); };
    auto row = [&](float y)
    { return static_cast<int>(std::clamp((y - originY) * scale, 0.f, lastRow)); };
    for (std::size_t i = 0; i < count; ++i)
    {
        if (!boxes.isUsable(i))
            cellRanges[i] = {1, 0, 1, 0}; // an empty range: listed in no cell
        else
            cellRanges[i] = {column(boxes.minX[i]), column(boxes.maxX[i]), row(boxes.minY[i]),
                             row(boxes.maxY[i])};
    }
}

// Calls visit(cell, covered, flags) for each cell of the range (cell = row * width + column;
// flags = the entry's kFirstColumnFlag / kFirstRowFlag).
// Four calls for small boxes: most boxes cover one cell, two (side by side or one above the
// other) or 2 x 2, and all of them get the same four calls, so the caller needs no branch: a
// call for a column or row the box does not reach names one of the box's own cells again, with
// covered = 0 (add nothing, take no place). Why: whether the next box crosses a column border
// (one time in three for an average box) or a row border is unpredictable, and the CPU's wrong
// guesses cost more than the extra calls (measured: docs/performance.md).
// Bigger boxes get one call per cell they cover.
template <typename Visit>
void BaselineGrid::forEachCell(const CellRange& range, std::size_t width, Visit visit)
{
    // 1 if the box reaches the next column (row), 0 if not. Empty-range wrap-around: for an
    // empty range (x1 = x0 - 1) the unsigned -1 is the largest size_t, so it fails `<= 1` and
    // takes the loops below, which run zero times: no extra test for empty ranges.
    const std::size_t right = std::size_t(range.x1 - range.x0);
    const std::size_t down = std::size_t(range.y1 - range.y0);
    const std::size_t cell = std::size_t(range.y0) * width + std::size_t(range.x0);
    if (right <= 1 && down <= 1)
    {
        // The cell below and to the right is covered only if the box reaches both.
        visit(cell + down * width + right, std::uint32_t(right & down), 0u);
        visit(cell + down * width, std::uint32_t(down), kFirstColumnFlag);
        visit(cell + right, std::uint32_t(right), kFirstRowFlag);
        visit(cell, 1u, kBothFlags);
        return;
    }
    for (int cy = range.y0; cy <= range.y1; ++cy) // nothing for an empty range (x0 > x1)
        for (int cx = range.x0; cx <= range.x1; ++cx)
            visit(std::size_t(cy) * width + std::size_t(cx), 1u,
                  (cx == range.x0 ? kFirstColumnFlag : 0u) | (cy == range.y0 ? kFirstRowFlag : 0u));
}

void BaselineGrid::listCells()
{
    const std::size_t count = boxes.size();
    const std::size_t cellCount = std::size_t(columns) * std::size_t(rows);
    // Local copies: the compiler cannot tell that writing an entry leaves these unchanged, so
    // it would read them from memory again for every entry.
    const std::size_t width = std::size_t(columns);
    const CellRange* ranges = cellRanges.data();
    const float* minX = boxes.minX.data();
    const float* maxX = boxes.maxX.data();
    const float* minY = boxes.minY.data();
    const float* maxY = boxes.maxY.data();
    // A counting sort: count each cell's boxes, add up the counts so each cell knows where
    // its boxes end, then drop each box in from the end back. No hashing and no list per
    // cell: one array holds every cell's boxes back to back, reused every frame.
    cellStart.assign(cellCount + 1, 0);
    std::uint32_t* start = cellStart.data();
    for (std::size_t i = 0; i < count; ++i)
        forEachCell(ranges[i], width,
                    [start](std::size_t cell, std::uint32_t covered, std::uint32_t)
                    { start[cell] += covered; });
    for (std::size_t c = 1; c <= cellCount; ++c)
        start[c] += start[c - 1]; // now start[c] = end of cell c
    // The spare entry: one more at the end, written by the calls with covered = 0, so that
    // they need no branch either.
    const std::uint32_t spare = cellStart[cellCount];
    entries.resize(std::size_t(spare) + 1);
    Entry* out = entries.data();
    // Fill from the last box back, each cell from its end back: afterwards start[c] is the
    // start of cell c, and every cell's boxes are in item order.
    for (std::size_t i = count; i-- > 0;)
    {
        const Entry box = {minX[i], maxX[i], minY[i], maxY[i], std::uint32_t(i)};
        forEachCell(
            ranges[i], width,
            [start, out, spare, &box](std::size_t cell, std::uint32_t covered, std::uint32_t flags)
            {
                const std::uint32_t slot = start[cell] - covered;
                start[cell] = slot;
                Entry entry = box;
                entry.itemAndFlags |= flags;
                out[selectWithoutBranch(covered, slot, spare)] = entry;
            });
    }
}

void BaselineGrid::testCells()
{
    std::size_t found = 0;
    std::size_t tested = 0;
    std::vector<Pair>& cellPairs = cellOrderPairs;
    const std::size_t cellCount = std::size_t(columns) * std::size_t(rows);
    for (std::size_t cell = 0; cell < cellCount; ++cell)
    {
        const std::uint32_t begin = cellStart[cell];
        const std::uint32_t end = cellStart[cell + 1];
        if (end - begin < 2)
            continue; // most cells: nothing to test, and no hashing to find that out
        tested += std::size_t(end - begin) * (end - begin - 1) / 2;
        for (std::uint32_t p = begin; p < end; ++p)
        {
            const Entry a = entries[p];
            const std::uint32_t first = itemOf(a);
            // Room for every pair this row could find (the loop below writes unchecked).
            if (cellPairs.size() < found + (end - p))
                cellPairs.resize(std::max(2 * cellPairs.size(), found + (end - p)));
            for (std::uint32_t q = p + 1; q < end; ++q)
            {
                const Entry& b = entries[q];
                // Each pair once: only the top-left cell two boxes share reports them.
                const bool reportHere = isTopLeftSharedCell(a, b);
                const bool overlap = spansOverlap(a.minX, a.maxX, b.minX, b.maxX) &
                                     spansOverlap(a.minY, a.maxY, b.minY, b.maxY);
                // Branch-free append: always write the pair, move past it only on a hit.
                cellPairs[found] = {first, itemOf(b)};
                found += reportHere & overlap;
            }
        }
    }
    cellPairCount = found;
    lastStats.pairsTested = tested;
}

void BaselineGrid::dropPairsLayersForbid()
{
    // Layers rarely forbid anything (every mask all ones): then skip this pass entirely.
    const std::size_t count = boxes.size();
    bool anyRules = false;
    for (std::size_t i = 0; i < count; ++i)
        anyRules |= (boxes.mask[i] != 0xFFFFFFFF) | (boxes.layer[i] == 0);
    if (!anyRules)
        return;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < cellPairCount; ++k)
    {
        const Pair pair = cellOrderPairs[k];
        cellOrderPairs[kept] = pair;
        kept += boxes.allowed(pair.first, pair.second);
    }
    cellPairCount = kept;
}

void BaselineGrid::sortPairs(std::vector<Pair>& pairs)
{
    // Cells find pairs in space order; the interface promises (first, second) order. A
    // counting sort by `first` is one pass over the pairs (std::sort needs about 17 at
    // 100,000 pairs); pairs with the same first come from different cells only when a box
    // covers several cells, so those few are put in order by insertion sort.
    const std::size_t count = boxes.size();
    pairStart.assign(count + 1, 0);
    const Pair* cellPairs = cellOrderPairs.data();
    for (std::size_t k = 0; k < cellPairCount; ++k)
        ++pairStart[cellPairs[k].first + 1];
    for (std::size_t i = 0; i < count; ++i)
        pairStart[i + 1] += pairStart[i];
    pairs.resize(cellPairCount);
    for (std::size_t k = 0; k < cellPairCount; ++k)
        pairs[pairStart[cellPairs[k].first]++] =
            cellPairs[k]; // afterwards pairStart[i] = end of i's pairs
    // Now in order of `first`; the pairs of one box are mostly in order of `second` too. One
    // insertion sort over all the pairs fixes the few that are not: a pass over the pairs
    // whose "in order?" test is almost always yes (a sort per box was a loop per box, whose
    // number of rounds the CPU could not guess).
    // Pair key: (first, second) packed into one 64-bit number, so one comparison orders both.
    auto key = [](const Pair& pair)
    { return std::uint64_t(pair.first) << 32 | std::uint64_t(pair.second); };
    Pair* sorted = pairs.data();
    for (std::size_t k = 1; k < cellPairCount; ++k)
    {
        const Pair moving = sorted[k];
        if (key(moving) > key(sorted[k - 1]))
            continue;
        std::size_t j = k;
        for (; j > 0 && key(sorted[j - 1]) > key(moving); --j)
            sorted[j] = sorted[j - 1];
        sorted[j] = moving;
    }
}

void BaselineGrid::findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs)
{
    boxes.load(items);
    chooseGrid();
    assignCells();
    listCells();
    testCells();
    dropPairsLayersForbid();
    sortPairs(pairs);
    lastStats.pairsFound = pairs.size();
}

BroadphaseLayout BaselineGrid::layout() const
{
    BroadphaseLayout result;
    const std::size_t cellCount = std::size_t(columns) * std::size_t(rows);
    if (cellStart.size() != cellCount + 1)
        return result; // no findPairs yet
    result.gridOrigin = {originX, originY};
    result.cellSize = usedCellSize;
    result.columns = columns;
    result.rows = rows;
    result.boxesPerCell.resize(cellCount);
    for (std::size_t c = 0; c < cellCount; ++c)
        result.boxesPerCell[c] = cellStart[c + 1] - cellStart[c];
    return result;
}

} // namespace bench
