// BaselineGrid.h - the grid as it was before issue 31 (commit 388f19a's GridBroadphase, copied
// unchanged but for its name): broadphase_bench times the new grid against it in the same run,
// so "0.6x the old cost" is a ratio measured side by side, not against a number from another day.
// Ericson, Real-Time Collision Detection, 7.1: only boxes in the same cell are tested.
//
// Each frame: work out which cells each box covers, list every cell's boxes (a counting sort,
// so each list is in item order and needs no allocation once warmed up), then test only the
// boxes that share a cell. A box bigger than a cell is listed in every cell it covers. Two
// boxes that share several cells are reported once: only in the top-left cell they share.
#pragma once

#include "hitbox/broadphase/BoxArrays.h"
#include "hitbox/broadphase/Broadphase.h"

#include <cstdint>
#include <vector>

namespace bench
{
using hitbox::BoxArrays;
using hitbox::Broadphase;
using hitbox::BroadphaseItem;
using hitbox::BroadphaseLayout;
using hitbox::BroadphaseStats;
using hitbox::Pair;

class BaselineGrid : public Broadphase
{
public:
    // cellSize <= 0: gridCellSizeFor(the items' average side), worked out every frame.
    explicit BaselineGrid(float cellSize = 0.f);

    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override;
    const char* name() const override { return "BaselineGrid"; }
    BroadphaseStats stats() const override { return lastStats; }
    // The grid (its cellSize: the one the last findPairs used) and how many boxes each cell holds.
    BroadphaseLayout layout() const override;

private:
    void chooseGrid();
    void assignCells();
    void listCells();
    void testCells();
    void sortPairs(std::vector<Pair>& pairs);

    void dropPairsLayersForbid();

    // One entry per (cell, box): the box's edges copied next to its cell's other boxes, so
    // testing a cell reads memory in order. 20 bytes: filling cells in random order costs a
    // memory write per entry, so smaller entries are faster (layers are checked afterwards,
    // on the few pairs found, instead of being copied into every entry).
    struct Entry
    {
        float minX, maxX, minY, maxY;
        // Packed index and flags (one 32-bit word instead of three): the item's index in the
        // low 30 bits, and two flags in the top two bits saying whether this cell is in the
        // box's leftmost column (kFirstColumnFlag) and top row (kFirstRowFlag).
        std::uint32_t itemAndFlags;
    };
    static constexpr std::uint32_t kFirstColumnFlag = 1u << 30;
    static constexpr std::uint32_t kFirstRowFlag = 1u << 31;
    static constexpr std::uint32_t kBothFlags = kFirstColumnFlag | kFirstRowFlag;
    static constexpr std::uint32_t kItemIndexMask = ~kBothFlags; // the low 30 bits

    // The item an entry belongs to: its packed word without the flags.
    static std::uint32_t itemOf(const Entry& entry) { return entry.itemAndFlags & kItemIndexMask; }
    // Report-once rule: boxes sharing several cells are reported only in the top-left cell they
    // share, the one in the leftmost column of one of them and the top row of one of them.
    static bool isTopLeftSharedCell(const Entry& a, const Entry& b)
    {
        return ((a.itemAndFlags | b.itemAndFlags) & kBothFlags) == kBothFlags;
    }

    float fixedCellSize;
    BoxArrays boxes;
    BroadphaseStats lastStats;

    // The grid of the last frame: cell (cx, cy) starts at origin + (cx, cy) * usedCellSize.
    float originX = 0.f, originY = 0.f, usedCellSize = 1.f;
    int columns = 1, rows = 1;

    // Per item: the range of cells it covers (inclusive). Empty (x0 > x1) for NaN boxes.
    // One struct per item, so the two passes over the items read one place per item.
    struct CellRange
    {
        int x0, x1, y0, y1;
    };
    // Calls visit(cell, covered, flags) for the cells of a range (see the .cpp).
    template <typename Visit>
    static void forEachCell(const CellRange& range, std::size_t width, Visit visit);
    std::vector<CellRange> cellRanges;
    // Cell c's boxes are entries [cellStart[c], cellStart[c + 1]), in item order.
    std::vector<std::uint32_t> cellStart;
    // The last entry is a spare that listCells writes to instead of branching (forEachCell).
    std::vector<Entry> entries;
    std::size_t cellPairCount = 0;
    std::vector<Pair> cellOrderPairs;     // the pairs in the order the cells found them
    std::vector<std::uint32_t> pairStart; // counting sort of the pairs by `first`
};

} // namespace bench
