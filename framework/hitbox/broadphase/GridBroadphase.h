// GridBroadphase.h - a flat uniform grid (Ericson, Real-Time Collision Detection, 7.1):
// only boxes in the same cell are tested.
//
// Each frame: work out which cells each box covers, list every cell's boxes (a counting sort,
// so each list is in item order and needs no allocation once warmed up), then test only the
// boxes that share a cell. A box bigger than a cell is listed in every cell it covers. Two
// boxes that share several cells are reported once: only in the lowest cell they share.
#pragma once

#include "hitbox/broadphase/BoxArrays.h"
#include "hitbox/broadphase/Broadphase.h"

namespace hitbox
{

class GridBroadphase : public Broadphase
{
public:
    // cellSize <= 0: pick it each frame from the items' average size.
    explicit GridBroadphase(float cellSize = 0.f);

    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override;
    const char* name() const override { return "Grid"; }
    BroadphaseStats stats() const override { return lastStats; }
    // The grid and how many boxes each cell holds.
    BroadphaseLayout layout() const override;

    // The cell size used by the last findPairs, in pixels.
    float getCellSize() const { return usedCellSize; }

private:
    void chooseGrid();
    void assignCells();
    void listCells();
    void testCells();
    void sortPairs(std::vector<Pair>& pairs);

    void dropPairsLayersForbid();

    // One entry per (cell, box): the box's numbers copied next to its cell's other boxes,
    // so testing a cell reads memory in order. 20 bytes: filling cells in random order costs
    // a memory write per entry, so smaller entries are faster (layers are checked afterwards,
    // on the few pairs found, instead of being copied into every entry).
    struct Entry
    {
        float minX, maxX, minY, maxY;
        std::uint32_t itemAndFirstCell; // the item index | kFirstColumn | kFirstRow
    };
    static constexpr std::uint32_t kItemBits = 0x3FFFFFFF;
    static constexpr std::uint32_t kFirstColumn = 1u << 30; // the box's leftmost column
    static constexpr std::uint32_t kFirstRow = 1u << 31;    // the box's top row

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
    // Calls visit(cell, covered, firstCell) for the cells of a range (see the .cpp).
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

} // namespace hitbox
