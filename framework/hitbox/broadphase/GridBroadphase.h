// GridBroadphase.h - a flat uniform grid (seed 002's spatial partitioning: "only test
// objects in the same partition").
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
    // Draws the grid lines and outlines the cells that hold at least one box.
    void drawDebug(DebugRenderer& debug) const override;

    // The cell size used by the last findPairs, in pixels.
    float getCellSize() const { return usedCellSize; }

private:
    void chooseGrid();
    void assignCells();
    void listCells();
    void testCells();
    void sortPairs(std::vector<Pair>& pairs);

    // One entry per (cell, box): the box's numbers copied next to its cell's other boxes,
    // so testing a cell reads memory in order, and filling a cell writes one cache line.
    struct Entry
    {
        float minX, maxX, minY, maxY;
        std::uint32_t item;
        std::uint32_t layer, mask;
        std::uint32_t firstCell; // bit 0: the box's first column, bit 1: its first row
    };

    float fixedCellSize;
    BoxArrays boxes;
    BroadphaseStats lastStats;

    // The grid of the last frame: cell (cx, cy) starts at origin + (cx, cy) * usedCellSize.
    float originX = 0.f, originY = 0.f, usedCellSize = 1.f;
    int columns = 1, rows = 1;

    // Per item: the range of cells it covers (inclusive). Empty (x0 > x1) for NaN boxes.
    std::vector<int> cellX0, cellY0, cellX1, cellY1;
    // Cell c's boxes are entries [cellStart[c], cellStart[c + 1]), in item order.
    std::vector<std::uint32_t> cellStart;
    std::vector<Entry> entries;
    std::size_t cellPairCount = 0;
    std::vector<Pair> cellOrderPairs;     // the pairs in the order the cells found them
    std::vector<std::uint32_t> pairStart; // counting sort of the pairs by `first`
};

} // namespace hitbox
