// GridBroadphase.h - a flat uniform grid (Ericson, Real-Time Collision Detection, 7.1):
// only boxes in the same cell are tested.
//
// Each frame: work out which cells each box covers, list every cell's boxes (a counting sort,
// so each list is in item order and needs no allocation once warmed up), then test only the
// boxes that share a cell. A box bigger than a cell is listed in every cell it covers. Two
// boxes that share several cells are reported once: only in the top-left cell they share.
// The tricks that make it fast are named in GridBroadphase.cpp and measured in
// docs/performance.md.
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace hitbox
{

class SecondThread;

// The order GridBroadphase::findPairs reports its pairs in.
enum class PairOrder
{
    // By (first, second), as Broadphase promises: a counting sort after the tests.
    Sorted,
    // The order the cells found them: cells row by row, in a cell by item. Every pair still has
    // first < second; the order is the same every run and with one or two threads, but it
    // changes when boxes move to other cells. Cheaper: no sort.
    CellOrder
};

// Below this many boxes a second thread costs more to start than it saves (a frame of 10,000
// boxes takes about 0.3 ms, starting a thread tens of microseconds): one thread is used.
constexpr std::size_t kGridTwoThreadsFromItems = 20000;

struct GridSettings
{
    float cellSize = 0.f; // <= 0: the cell rule (GridCellRule.h) for the items, every frame
    // With the rule: its cell times this, to try other sizes (lab 8's [ and ]). Not above 0, or
    // not finite: 1.
    float cellScale = 1.f;
    PairOrder order = PairOrder::Sorted;
    // 1 or 2 (other values: 1 below 2, 2 above). Two threads split the work in halves from
    // twoThreadsFromItems boxes; the pairs and their order are the same as with one.
    int threads = 1;
    std::size_t twoThreadsFromItems = kGridTwoThreadsFromItems; // tests lower it to 0
    // true: the SSE steps where the compiler offers SSE (x86-64); false: the plain C++ steps
    // every other machine (ARM, 32-bit x86) runs, so tests check both give the same pairs.
    bool simd = true;
    // With simd: true compares two entries per instruction (AVX) when the CPU has AVX (asked
    // at run time), false one (SSE). Off by default: measured 3-6 % slower on this workload
    // (docs/performance.md); kept, and tested, so the measurement can be repeated.
    bool eightWide = false;
};

class GridBroadphase : public Broadphase
{
public:
    // cellSize <= 0: the cell rule (GridCellRule.h) for the items' average side and coverage.
    // Worked out every frame, but last frame's grid is kept while the rule's cell is within
    // 1.25x of it and the boxes stay within a cell of it (any grid finds the same pairs; this
    // one saves a pass).
    explicit GridBroadphase(float cellSize = 0.f);
    explicit GridBroadphase(const GridSettings& settings);
    ~GridBroadphase() override; // stops the second thread, if one was started

    // Every pair once, first < second, in the settings' PairOrder (Sorted unless asked).
    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override;
    [[nodiscard]] const char* name() const override { return "Grid"; }
    [[nodiscard]] BroadphaseStats stats() const override { return lastStats; }
    // The grid (its cellSize: the one the last findPairs used) and how many boxes each cell holds.
    [[nodiscard]] BroadphaseLayout layout() const override;
    [[nodiscard]] const GridSettings& settings() const { return gridSettings; }
    // With two threads: CPU seconds the second thread spent in the last findPairs beyond the
    // calling thread's own share of the same work (0 with one thread). The calling thread's
    // CPU time plus this is the CPU time of the frame's longest chain of work.
    [[nodiscard]] double lastWorkerExtraSeconds() const { return workerExtraSeconds; }

private:
    // A box as the pair test wants it: (minX, minY, -maxX, -maxY), so one four-wide "less
    // than" against the other box's (maxX, maxY, -minX, -minY) tests both axes (see .cpp).
    struct alignas(16) Edges
    {
        float minX, minY, negMaxX, negMaxY;
    };
    // The cells a box covers, inclusive; empty (x0 > x1) for NaN boxes.
    struct CellRange
    {
        int x0, x1, y0, y1;
    };
    // The grid: cell (cx, cy) starts at origin + (cx, cy) * cell.
    struct Shape
    {
        float originX = 0.f, originY = 0.f, cell = 1.f;
        int columns = 1, rows = 1;
    };
    // One thread's half of the items (the first or the second half, always split the same way
    // so sums come out the same with one or two threads) and what it found.
    struct Half
    {
        std::size_t begin = 0, end = 0; // items
        float left = 0.f, top = 0.f, right = 0.f, bottom = 0.f;
        double sideSum = 0.0;
        std::size_t usable = 0;
        bool anyRules = false;
        std::vector<std::uint32_t> cursor;      // per cell: this half's count, then where it fills
        std::size_t firstCell = 0, endCell = 0; // the cells this half tests
        std::unique_ptr<Pair[]> found;          // foundRoom pairs; the first foundCount are real
        std::size_t foundRoom = 0;
        std::size_t foundCount = 0;
        std::vector<Edges> gathered; // the edges of the cell being tested (plain C++ steps)
        // Four at a time: the cell being tested as columns (minX, minY, -maxX, -maxY, item
        // word), each column laneRoom long, so one box is tested against four in one step.
        std::vector<float> laneEdges;
        std::vector<std::uint32_t> laneWords;
    };

    struct CellFinder;
    // The second thread, started on the first frame that uses two (nullptr if none can start).
    [[nodiscard]] SecondThread* helperThread();
    void prepare(Half& half);
    void countCells(Half& half);
    [[nodiscard]] Shape idealShape(std::size_t count) const;
    // The usable boxes' mean side ((width + height) / 2) in the last prepare(); 0 if none.
    [[nodiscard]] double averageSideOfLastFrame() const;
    [[nodiscard]] bool keepsShape(const Shape& ideal, std::size_t count) const;
    void startCells();
    void fillCells(Half& half);
    void testCells(Half& half);
    // The pairs found in half's cells, written to `out`, one pair test at a time in plain C++
    // (machines without SSE, and GridSettings::simd = false).
    [[nodiscard]] std::size_t testCellRangePlain(Half& half, Pair* out) const;
    // The same pairs in the same order, one box against four others per SSE step (the .cpp's
    // "Four at a time"); only where SSE is compiled.
    [[nodiscard]] std::size_t testCellRangeFourWide(Half& half, Pair* out) const;
    void gatherPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs);
    void sortPairs(std::vector<Pair>& pairs);

    // Report-once rule: a pair is reported only in the top-left cell the two boxes share: the
    // one in the leftmost column of one of them and the top row of one of them. Flags in the
    // top two bits of an entry's item word.
    static constexpr std::uint32_t kFirstColumnFlag = 1u << 30;
    static constexpr std::uint32_t kFirstRowFlag = 1u << 31;
    static constexpr std::uint32_t kBothFlags = kFirstColumnFlag | kFirstRowFlag;
    static constexpr std::uint32_t kItemIndexMask = ~kBothFlags; // the low 30 bits

    GridSettings gridSettings;
    BroadphaseStats lastStats;
    double workerExtraSeconds = 0.0;
    bool hasShape = false;
    Shape shape;
    Half halves[2];
    std::size_t itemCount = 0;
    bool hasAvx = false;                          // the CPU runs AVX (eightWide)
    std::uint32_t largestCell = 0;                // the most entries in one cell this frame
    const BroadphaseItem* currentItems = nullptr; // during findPairs
    std::vector<Edges> edges;                     // per item
    std::vector<std::uint32_t> cellWords;         // per item: its cells, packed (see .cpp)
    std::vector<std::uint32_t> start;             // cell c's entries are [start[c], start[c + 1])
    // The entries, cell after cell: each box's item word (index and flags; its edges are in
    // `edges`). The last two entries are spares the two fill threads write to instead of
    // branching (forEachCell in the .cpp).
    std::vector<std::uint32_t> cellItems;
    std::vector<Pair> cellOrderPairs;     // PairOrder::Sorted: the pairs before sorting
    std::vector<std::uint32_t> pairStart; // counting sort of the pairs by `first`
    // Runs one half of each pass with two threads. Last, so it stops before the rest goes.
    std::unique_ptr<SecondThread> secondThread;
};

} // namespace hitbox
