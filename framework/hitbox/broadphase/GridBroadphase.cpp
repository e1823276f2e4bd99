// The grid's tricks, each named once here and measured in docs/performance.md:
//   - Negated-max edges: a box is stored as (minX, minY, -maxX, -maxY), so "less than" on all
//     four numbers tests a pair on both axes; the plain C++ steps make the same four compares
//     where SSE is missing (ARM, 32-bit x86 without SSE2).
//   - Four at a time: the tests copy a busy cell into five columns (the four edges and the
//     item words) and compare one box with four others per SSE step, flags and all.
//   - Transposed copy: four entries' edges are copied into the columns with one SSE 4 x 4
//     transpose instead of sixteen single floats.
//   - Counted places: a 16-entry table gives the write places of a step's four pairs, so the
//     write position moves once per step, not after every write.
//   - Few-box cells one at a time: cells of fewer than kFourAtATimeFrom boxes skip the column
//     copy and test each pair straight from the per-item edges.
//   - One preparation pass: loading a box, its share of the grid's bounds and average size,
//     its cells and the count of its cells happen in one walk over the items.
//   - Four-lane preparation: in that pass the usual box is loaded, bounded and placed in its
//     cells with SSE steps on its four numbers at once (GridSettings::simd = false, and
//     machines without SSE, run the same steps in plain C++; the tests run both).
//   - Last frame's grid: the cells are worked out with last frame's grid and only worked out
//     again when the boxes outgrew it or their size changed (any grid gives the right pairs).
//   - Loop-free listing: every small box makes the same four cell visits (forEachCell).
//   - Counting with covered: those visits name the real neighbour cells and add 0 or 1 to
//     their counters, so no visit picks a target first (forFourCells).
//   - Packed cell words: the fill reads each box's cells from 4 bytes, not a 16-byte range.
//   - Item-word entries: a cell entry is the box's 4-byte item word only (4 bytes a
//     box-in-a-cell, which stay in the cache while written in scattered places); the tests
//     copy each busy cell's edges from the per-item array.
//   - Prefetched edges: the tests ask for the next 24 entries' edges while a cell is tested,
//     so the copies find them in the cache.
//   - Eight-wide compares (GridSettings::eightWide, off: measured slower): two entries per
//     AVX compare, chosen at run time by asking the CPU; SSE or plain C++ otherwise.
//   - Pairs in cell order: no sort when the caller does not need (first, second) order.
//   - Two halves: with two threads, each half of the items is prepared and filled in by one
//     thread, and each half of the cells tested by one; the halves never change the result.
//   - One kept helper: the second thread is started once and given each pass's half
//     (SecondThread.h), not started and stopped for every pass.
#include "hitbox/broadphase/GridBroadphase.h"

#include "hitbox/broadphase/BoxArrays.h"
#include "hitbox/broadphase/GridCellRule.h"
#include "hitbox/broadphase/SecondThread.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/platform/Platform.h"
#include "hitbox/platform/Prefetch.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <system_error>

#if defined(__SSE2__) || defined(_M_X64) || defined(_M_AMD64)
#include <emmintrin.h>
#define HITBOX_GRID_SSE 1
#endif

// Eight-wide compares (AVX) on 64-bit x86 only, compiled for AVX in this one function's
// attribute and used only when the CPU says it has AVX (checked at run time, cpuHasAvx): the
// rest of the program stays plain x86-64, so it runs on CPUs without AVX.
#if defined(HITBOX_GRID_SSE) && (defined(__x86_64__) || defined(_M_X64) || defined(_M_AMD64))
#include <immintrin.h>
#define HITBOX_GRID_AVX 1
#if defined(_MSC_VER) && !defined(__clang__)
#include <intrin.h>
#define HITBOX_TARGET_AVX // MSVC compiles AVX intrinsics without a flag
#else
#define HITBOX_TARGET_AVX __attribute__((target("avx")))
#endif
#endif

namespace hitbox
{
namespace
{

// Never more than this many cells per item, so empty space (or one far-away object) cannot
// make the grid huge: the cell size grows instead.
constexpr double kMaxCellsPerItem = 4.0;
// Far below anything a game uses, and 1 / this is still a float.
constexpr double kSmallestCellSize = 1e-30;
// Last frame's grid is kept while the ideal cell is within this factor of it.
constexpr double kKeepCellWithin = 1.25;

// Branch-free select: `oneOrZero ? ifOne : ifZero` with bit masks. Where g++ 12 compiles the
// `?:` to a jump, the CPU has to guess it, and a wrong guess costs more than these three steps.
inline std::uint32_t selectWithoutBranch(std::uint32_t oneOrZero, std::uint32_t ifOne,
                                         std::uint32_t ifZero)
{
    const std::uint32_t keep = 0u - oneOrZero; // unsigned wrap-around: 0 - 1 is all ones
    return (ifOne & keep) | (ifZero & ~keep);
}

// Resizes `buffer` to `size`, growing its memory by a quarter more than asked when it must
// grow, so boxes that crowd a little more each frame do not make it copy itself every frame.
template <typename T>
void growWithRoom(std::vector<T>& buffer, std::size_t size)
{
    if (buffer.capacity() < size)
        buffer.reserve(size + size / 4);
    buffer.resize(size);
}

// Runs work(0) and work(1), work(1) on `helper` when there is one, and returns how many CPU
// seconds the helper spent beyond the calling thread (0 without a helper).
template <typename Work>
double runHalves(SecondThread* helper, Work work)
{
    if (helper == nullptr)
    {
        work(0);
        work(1);
        return 0.0;
    }
    double helperSeconds = 0.0;
    helper->start(
        [&work, &helperSeconds]
        {
            const double begin = platform::threadCpuSeconds();
            work(1);
            helperSeconds = platform::threadCpuSeconds() - begin;
        });
    const double begin = platform::threadCpuSeconds();
    work(0);
    const double ownSeconds = platform::threadCpuSeconds() - begin;
    helper->finish();
    return std::max(0.0, helperSeconds - ownSeconds);
}

// The four calls of a box that covers one cell, two or 2 x 2: `cell` its top-left cell,
// right / down 1 if it reaches the next column / row.
// Counting with covered: each call names the neighbour cell whether the box reaches it or not,
// and the caller adds `covered` (0 or 1) to that cell's counter, so no call has to pick a
// target first (three selects less per box in the preparation and in the fill). A neighbour
// can lie past the grid's last cell (cell + width + 1 at most): the counters have
// counterCount's few more, which only ever get 0 added.
template <typename Visit>
inline void forFourCells(std::size_t cell, std::size_t right, std::size_t down, std::size_t width,
                         std::uint32_t firstColumn, std::uint32_t firstRow, Visit visit)
{
    // The cell below and to the right is covered only if the box reaches both.
    visit(cell + width + 1, std::uint32_t(right & down), 0u);
    visit(cell + width, std::uint32_t(down), firstColumn);
    visit(cell + 1, std::uint32_t(right), firstRow);
    visit(cell, 1u, firstColumn | firstRow);
}

// Calls visit(target, covered, flags) for each cell of the range: target = row * width +
// column, flags = the entry's kFirstColumnFlag / kFirstRowFlag.
// Loop-free listing: small boxes get four calls. Most boxes cover one cell, two (side by side
// or one above the other) or 2 x 2, and all of them get the same four calls, so the caller
// needs no branch: a call for a column or row the box does not reach has covered = 0 (and
// names the neighbour cell all the same, see forFourCells). Why: whether the next box crosses
// a column border (one time in three for an average box) or a row border is unpredictable,
// and the CPU's wrong guesses cost more than the extra calls. Bigger boxes get one call per
// cell they cover. Measured: docs/performance.md.
template <typename Range, typename Visit>
inline void forEachCell(const Range& range, std::size_t width, std::uint32_t firstColumn,
                        std::uint32_t firstRow, Visit visit)
{
    // 1 if the box reaches the next column (row), 0 if not. Empty-range wrap-around: for an
    // empty range (x1 = x0 - 1) the unsigned -1 is the largest size_t, so it fails `<= 1` and
    // takes the loops below, which run zero times: no extra test for empty ranges.
    const std::size_t right = std::size_t(range.x1 - range.x0);
    const std::size_t down = std::size_t(range.y1 - range.y0);
    const std::size_t cell = std::size_t(range.y0) * width + std::size_t(range.x0);
    if (right <= 1 && down <= 1)
    {
        forFourCells(cell, right, down, width, firstColumn, firstRow, visit);
        return;
    }
    for (int cy = range.y0; cy <= range.y1; ++cy) // nothing for an empty range (x0 > x1)
        for (int cx = range.x0; cx <= range.x1; ++cx)
            visit(std::size_t(cy) * width + std::size_t(cx), 1u,
                  (cx == range.x0 ? firstColumn : 0u) | (cy == range.y0 ? firstRow : 0u));
}

// Packed cell words: what the fill pass needs of a box's cells in 4 bytes, not a 16-byte
// range (at 100,000 boxes 1.2 MB less written and read again every frame): its top-left cell
// in the low 30 bits, "reaches the next column" in bit 30, "reaches the next row" in bit 31.
// kWideBox for the rare others (bigger than 2 x 2 cells, NaN, or a cell number that does not
// fit): the fill works their cells out again from their edges.
constexpr std::uint32_t kWideBox = 0xFFFFFFFFu;
constexpr std::size_t kPackedCellLimit = (std::size_t(1) << 30) - 1;

template <typename Range>
inline std::uint32_t packCells(const Range& range, std::size_t width)
{
    const std::size_t right = std::size_t(range.x1 - range.x0); // huge when empty, as above
    const std::size_t down = std::size_t(range.y1 - range.y0);
    const std::size_t cell = std::size_t(range.y0) * width + std::size_t(range.x0);
    if (right > 1 || down > 1 || cell >= kPackedCellLimit)
        return kWideBox;
    return std::uint32_t(cell) | std::uint32_t(right) << 30 | std::uint32_t(down) << 31;
}

// Prefetched edges: how many entries ahead the tests ask for the boxes' edges.
constexpr std::uint32_t kFetchAhead = 24;

// Calls testCell(begin, end) for every cell in [firstCell, endCell) with two entries or more
// (most cells have fewer: nothing to test, and no hashing to find that out). Prefetched edges:
// first it asks for the edges of the next kFetchAhead entries, so they arrive while this cell
// is tested (the cache fetches on its own only what is read in order).
template <typename Edge, typename TestCell>
void forEachBusyCell(const std::uint32_t* start, const std::uint32_t* items, const Edge* itemEdges,
                     std::uint32_t indexMask, std::size_t firstCell, std::size_t endCell,
                     TestCell testCell)
{
    std::uint32_t fetched = start[firstCell]; // entries whose edges were asked for
    const std::uint32_t lastEntry = start[endCell];
    for (std::size_t cell = firstCell; cell < endCell; ++cell)
    {
        const std::uint32_t begin = start[cell];
        const std::uint32_t end = start[cell + 1];
        if (end - begin < 2)
            continue;
        const std::uint32_t until = std::min(end + kFetchAhead, lastEntry);
        for (fetched = std::max(fetched, end); fetched < until; ++fetched)
            platform::prefetch(itemEdges + (items[fetched] & indexMask));
        testCell(begin, end);
    }
}

#if defined(HITBOX_GRID_AVX)
bool cpuHasAvx(); // below, with the eight-wide tests
#endif

#if defined(HITBOX_GRID_SSE)
// Counted places: for the four hit bits of one four-wide step (bit k: the pair with lane k is
// a hit), where lanes 1, 2 and 3 are written (2 bits each: the hits in the lanes before them)
// and, from bit 6, how many hits there are. With it the write position moves once per step
// instead of after each of the four writes, each of which waited for the one before.
constexpr std::uint16_t placesFor(unsigned hits)
{
    const unsigned one = hits & 1u;
    const unsigned two = one + ((hits >> 1) & 1u);
    const unsigned three = two + ((hits >> 2) & 1u);
    const unsigned all = three + ((hits >> 3) & 1u);
    return std::uint16_t(one | two << 2 | three << 4 | all << 6);
}
constexpr std::uint16_t kHitPlaces[16] = {
    placesFor(0),  placesFor(1),  placesFor(2),  placesFor(3), placesFor(4),  placesFor(5),
    placesFor(6),  placesFor(7),  placesFor(8),  placesFor(9), placesFor(10), placesFor(11),
    placesFor(12), placesFor(13), placesFor(14), placesFor(15)};

// Few-box cells one at a time: cells of fewer boxes than this test each pair on its own, not
// four at a time (lab 8's cells hold 2-3 balls, the benchmark's about 12 boxes; 5 and 8
// measured the same there, docs/performance.md).
constexpr std::uint32_t kFourAtATimeFrom = 5;
#endif

// Counters a half keeps per cell: the grid's cells, then room for forFourCells' neighbours of
// the last row (past the last cell by up to width + 1), which are only ever given 0.
inline std::size_t counterCount(std::size_t columns, std::size_t rows)
{
    return columns * rows + columns + 1;
}

} // namespace

GridBroadphase::GridBroadphase(float cellSize) : GridBroadphase(GridSettings{cellSize}) {}

GridBroadphase::GridBroadphase(const GridSettings& settings) : gridSettings(settings)
{
#if defined(HITBOX_GRID_AVX)
    hasAvx = cpuHasAvx();
#endif
}

// Which cells a box covers under a grid: the grid's numbers copied once into a small struct,
// so the loops keep them in registers (the compiler cannot tell that writing an entry leaves
// the members unchanged, and would read them again for every box).
struct GridBroadphase::CellFinder
{
    float originX, originY, scale, lastColumn, lastRow;
    std::size_t width;

    explicit CellFinder(const Shape& shape)
        : originX(shape.originX), originY(shape.originY), scale(1.f / shape.cell),
          lastColumn(static_cast<float>(shape.columns - 1)),
          lastRow(static_cast<float>(shape.rows - 1)), width(std::size_t(shape.columns))
    {
    }
    // [slide:grid-cells]
    // Which cells does a box cover? Divide by the cell size and round down. Clamping to the
    // grid keeps the answer monotonic (a box further right never gets a smaller column), so
    // two overlapping boxes always share a cell, even boxes outside the grid.
    int column(float x) const
    {
        return static_cast<int>(std::clamp((x - originX) * scale, 0.f, lastColumn));
    }
    int row(float y) const
    {
        return static_cast<int>(std::clamp((y - originY) * scale, 0.f, lastRow));
    }
    // [/slide]
    CellRange cellsOf(const Edges& box) const
    {
        const bool usable = box.minX <= -box.negMaxX && box.minY <= -box.negMaxY;
        return usable ? CellRange{column(box.minX), column(-box.negMaxX), row(box.minY),
                                  row(-box.negMaxY)}
                      : CellRange{1, 0, 1, 0}; // an empty range: listed in no cell
    }
    // [slide:grid-insert]
    // A counting sort: count each cell's boxes, add up the counts so each cell knows where its
    // boxes go, then drop each box in. No hashing and no list per cell: one array holds every
    // cell's boxes back to back, reused every frame.
    void count(const CellRange& range, std::uint32_t* counts) const
    {
        forEachCell(range, width, 0u, 0u,
                    [counts](std::size_t target, std::uint32_t covered, std::uint32_t)
                    { counts[target] += covered; });
    }
    // [/slide]
};

void GridBroadphase::prepare(Half& half)
{
    // One preparation pass: the box the tests use, the grid's bounds and average size, and
    // (with last frame's grid) the box's cells and their counts, in one walk over the items.
    const BroadphaseItem* source = currentItems;
    Edges* out = edges.data();
    std::uint32_t* outWords = cellWords.data();
    const CellFinder finder(shape);
    const bool count = hasShape;
    if (count)
        half.cursor.assign(counterCount(std::size_t(shape.columns), std::size_t(shape.rows)), 0);
    std::uint32_t* counts = half.cursor.data();
    const float inf = std::numeric_limits<float>::infinity();
    // A box edge can be +-infinity when left + width overflowed; the grid only needs finite
    // numbers (boxes beyond it land in its edge cells).
    const float largest = std::numeric_limits<float>::max();
    float left = inf, top = inf, right = -inf, bottom = -inf;
    double sideSum = 0.0;
    std::size_t usable = 0;
    std::uint32_t rules = 0;
    // Any box, in plain C++: NaN and infinite boxes, negative sizes, and every box where the
    // SSE path below is not compiled.
    auto loadOne = [&](std::size_t i)
    {
        const Box& box = source[i].box;
        Edges edge = {inf, inf, inf, inf}; // min = +inf, max = -inf: overlaps nothing
        // All four finite, in one test: x - x is 0 for a finite x and NaN for NaN or
        // infinity, and NaN spreads through the sum (four isfinite calls were four branches).
        const float zeroIfFinite = (box.left - box.left) + (box.top - box.top) +
                                   (box.width - box.width) + (box.height - box.height);
        if (zeroIfFinite == 0.f)
        {
            // The same arithmetic as boxVsBox (normalised(), then left + width), so the
            // broadphase and the exact test agree to the last bit, even at huge coordinates.
            const Box upright = normalised(box);
            const float maxX = upright.left + upright.width;
            const float maxY = upright.top + upright.height;
            edge = {upright.left, upright.top, -maxX, -maxY};
            const float minXFinite = std::clamp(upright.left, -largest, largest);
            const float minYFinite = std::clamp(upright.top, -largest, largest);
            const float maxXFinite = std::clamp(maxX, -largest, largest);
            const float maxYFinite = std::clamp(maxY, -largest, largest);
            left = std::min(left, minXFinite);
            top = std::min(top, minYFinite);
            right = std::max(right, maxXFinite);
            bottom = std::max(bottom, maxYFinite);
            sideSum +=
                0.5 * ((double(maxXFinite) - minXFinite) + (double(maxYFinite) - minYFinite));
            ++usable;
        }
        out[i] = edge;
        if (count)
        {
            const CellRange range = finder.cellsOf(edge);
            outWords[i] = packCells(range, finder.width);
            finder.count(range, counts);
        }
    };
    std::size_t i = half.begin;
#if defined(HITBOX_GRID_SSE)
    if (!gridSettings.simd)
        i = half.end; // the plain loop below does every box
    // Four lanes per box: the usual box (finite, sizes not negative) is loaded, bounded and
    // placed in its cells with four-wide SSE steps and no branch but the one that sends the
    // rare other boxes to loadOne. The same float operations as loadOne, so the same edges
    // and cells to the last bit; the bounds and sizes are summed in other lanes (and the
    // sizes in another order), which moves the grid's cell size in its last bits at most,
    // and any grid finds the same pairs.
    const __m128 signs = _mm_set_ps(-0.f, -0.f, 0.f, 0.f);
    const __m128 lowest = _mm_set1_ps(-largest);
    const __m128 highest = _mm_set1_ps(largest);
    const __m128 origin =
        _mm_set_ps(finder.originY, finder.originX, finder.originY, finder.originX);
    const __m128 scale = _mm_set1_ps(finder.scale);
    const __m128 last =
        _mm_set_ps(finder.lastRow, finder.lastColumn, finder.lastRow, finder.lastColumn);
    const __m128 zero = _mm_setzero_ps();
    __m128 lowBounds = _mm_set1_ps(inf);   // (left, top, -, -)
    __m128 highBounds = _mm_set1_ps(-inf); // (-, -, right, bottom)
    __m128d sizeSums = _mm_setzero_pd();   // (sum of widths, sum of heights)
    std::size_t fastBoxes = 0;
    for (; i < half.end; ++i)
    {
        const BroadphaseItem& item = source[i];
        rules |= ~item.mask | std::uint32_t(item.layer == 0);
        const __m128 box = _mm_loadu_ps(&item.box.left); // (left, top, width, height)
        // Finite (x - x == 0) and no negative size, all four lanes at once.
        const int finite = _mm_movemask_ps(_mm_cmpeq_ps(_mm_sub_ps(box, box), zero));
        const int negative = _mm_movemask_ps(_mm_cmplt_ps(box, zero)) & 0xC;
        if (finite != 0xF || negative != 0)
        {
            loadOne(i);
            continue;
        }
        // (left, top, left + width, top + height): the box's min and max corners.
        const __m128 corners = _mm_movelh_ps(box, _mm_add_ps(box, _mm_movehl_ps(box, box)));
        _mm_store_ps(&out[i].minX, _mm_xor_ps(corners, signs));
        const __m128 finiteCorners = _mm_min_ps(_mm_max_ps(corners, lowest), highest);
        lowBounds = _mm_min_ps(lowBounds, finiteCorners);
        highBounds = _mm_max_ps(highBounds, finiteCorners);
        sizeSums = _mm_add_pd(sizeSums,
                              _mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(finiteCorners, finiteCorners)),
                                         _mm_cvtps_pd(finiteCorners)));
        ++fastBoxes;
        if (count)
        {
            // column(x) and row(y) of both corners at once, as CellFinder works them out.
            const __m128 scaled = _mm_mul_ps(_mm_sub_ps(corners, origin), scale);
            const __m128i cells =
                _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(scaled, zero), last)); // (x0, y0, x1, y1)
            CellRange range;
            _mm_storeu_si128(reinterpret_cast<__m128i*>(&range),
                             _mm_shuffle_epi32(cells, _MM_SHUFFLE(3, 1, 2, 0)));
            outWords[i] = packCells(range, finder.width);
            finder.count(range, counts);
        }
    }
    alignas(16) float low[4], high[4];
    alignas(16) double sizes[2];
    _mm_store_ps(low, lowBounds);
    _mm_store_ps(high, highBounds);
    _mm_store_pd(sizes, sizeSums);
    left = std::min(left, low[0]);
    top = std::min(top, low[1]);
    right = std::max(right, high[2]);
    bottom = std::max(bottom, high[3]);
    sideSum += 0.5 * (sizes[0] + sizes[1]);
    usable += fastBoxes;
#endif
    for (std::size_t k = gridSettings.simd ? i : half.begin; k < half.end; ++k)
    {
        const BroadphaseItem& item = source[k];
        rules |= ~item.mask | std::uint32_t(item.layer == 0);
        loadOne(k);
    }
    half.left = left;
    half.top = top;
    half.right = right;
    half.bottom = bottom;
    half.sideSum = sideSum;
    half.usable = usable;
    half.anyRules = rules != 0;
}

void GridBroadphase::countCells(Half& half)
{
    // The grid changed: the cells again, with the new grid.
    half.cursor.assign(counterCount(std::size_t(shape.columns), std::size_t(shape.rows)), 0);
    std::uint32_t* counts = half.cursor.data();
    const CellFinder finder(shape);
    for (std::size_t i = half.begin; i < half.end; ++i)
    {
        const CellRange range = finder.cellsOf(edges[i]);
        cellWords[i] = packCells(range, finder.width);
        finder.count(range, counts);
    }
}

GridBroadphase::Shape GridBroadphase::idealShape(std::size_t count) const
{
    const Half& a = halves[0];
    const Half& b = halves[1];
    const std::size_t usable = a.usable + b.usable;
    const float left = usable > 0 ? std::min(a.left, b.left) : 0.f;
    const float top = usable > 0 ? std::min(a.top, b.top) : 0.f;
    const float right = usable > 0 ? std::max(a.right, b.right) : 0.f;
    const float bottom = usable > 0 ? std::max(a.bottom, b.bottom) : 0.f;
    Shape ideal;
    ideal.originX = left;
    ideal.originY = top;
    // Work in double: the extent of boxes at +-1e38 does not fit in a float.
    const double width = double(right) - left;
    const double height = double(bottom) - top;
    const float fixedCellSize = gridSettings.cellSize;
    const float scale = gridSettings.cellScale;
    const double ruleScale = scale > 0.f && std::isfinite(scale) ? double(scale) : 1.0;
    const double averageSide = averageSideOfLastFrame();
    double cell =
        fixedCellSize > 0.f ? fixedCellSize
        : usable > 0
            ? ruleScale * gridCellSizeFor(averageSide,
                                          gridCoverage(double(usable), averageSide, width, height))
            : 1.0;
    if (!(cell > 0.0) || !std::isfinite(cell))
        cell = std::max({width, height, 1.0}); // every box has zero size: one big cell
    // Cells are found by multiplying by 1 / cell size. For cells below about 1e-38 that is
    // infinity in float, and 0 * infinity is NaN, which has no cell: never go that small.
    cell = std::max(cell, kSmallestCellSize);
    // [slide:grid-size]
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
    // [/slide]
    ideal.columns = static_cast<int>(std::min(cellsX, maxCells));
    ideal.rows = static_cast<int>(std::min(cellsY, std::floor(maxCells / ideal.columns) + 1.0));
    ideal.cell = static_cast<float>(std::min(cell, double(std::numeric_limits<float>::max())));
    return ideal;
}

double GridBroadphase::averageSideOfLastFrame() const
{
    const std::size_t usable = halves[0].usable + halves[1].usable;
    // Both halves' sums added in the same order with one or two threads: the same grid.
    return usable > 0 ? (halves[0].sideSum + halves[1].sideSum) / double(usable) : 0.0;
}

bool GridBroadphase::keepsShape(const Shape& ideal, std::size_t count) const
{
    // Last frame's grid: any grid finds the right pairs (boxes outside it are clamped into its
    // edge cells), so keep it while it is nearly as good as the ideal one: a cell size within
    // kKeepCellWithin of the ideal, boxes no more than a cell beyond it, no more than a few
    // cells per box. Moving boxes then need no second pass to work out their cells again.
    if (!hasShape)
        return false;
    const double cell = shape.cell;
    const double ratio = cell / double(ideal.cell);
    if (!(ratio <= kKeepCellWithin && ratio >= 1.0 / kKeepCellWithin))
        return false;
    const double cells = double(shape.columns) * double(shape.rows);
    if (cells > kMaxCellsPerItem * double(count) + 16.0)
        return false;
    const double gridRight = double(shape.originX) + cell * shape.columns;
    const double gridBottom = double(shape.originY) + cell * shape.rows;
    const double idealRight = double(ideal.originX) + double(ideal.cell) * ideal.columns;
    const double idealBottom = double(ideal.originY) + double(ideal.cell) * ideal.rows;
    const bool covers = ideal.originX >= shape.originX - cell &&
                        ideal.originY >= shape.originY - cell && idealRight <= gridRight + cell &&
                        idealBottom <= gridBottom + cell;
    // ...and not much bigger than the boxes need (they gathered in one corner, say).
    const bool tight = shape.columns <= ideal.columns + 2 + ideal.columns / 4 &&
                       shape.rows <= ideal.rows + 2 + ideal.rows / 4;
    return covers && tight;
}

void GridBroadphase::startCells()
{
    // Where each cell's entries start, and where each half fills them from: half 0's boxes
    // first, then half 1's, so every cell lists its boxes in item order with any thread count.
    const std::size_t cellCount = std::size_t(shape.columns) * std::size_t(shape.rows);
    start.resize(cellCount + 1);
    std::uint32_t* first = halves[0].cursor.data();
    std::uint32_t* second = halves[1].cursor.data();
    std::uint32_t total = 0;
    std::size_t tested = 0;
    std::uint32_t largest = 0;
    for (std::size_t c = 0; c < cellCount; ++c)
    {
        const std::uint32_t inFirst = first[c];
        const std::uint32_t inCell = inFirst + second[c];
        largest = std::max(largest, inCell);
        start[c] = total;
        tested += std::size_t(inCell) * (inCell - (inCell > 0 ? 1u : 0u)) / 2;
        total += inCell;
        first[c] = start[c] + inFirst; // each half fills its part from the end back
        second[c] = total;
    }
    start[cellCount] = total;
    lastStats.pairsTested = tested;
    largestCell = largest;
    // Two spare entries, one per filling thread (forEachCell's covered = 0 calls write there).
    growWithRoom(cellItems, std::size_t(total) + 2);
    // Each half of the cells is tested by one thread: split where half the entries are.
    const std::size_t middle =
        std::size_t(std::lower_bound(start.begin(), start.end() - 1, total / 2) - start.begin());
    halves[0].firstCell = 0;
    halves[0].endCell = middle;
    halves[1].firstCell = middle;
    halves[1].endCell = cellCount;
    // Room for every pair a half could find (the tests write unchecked). Grows only, with room
    // to spare and without zeroing or copying: a frame whose boxes crowd a little more than
    // ever before would otherwise pay for clearing megabytes (measured: 4 ms at 100,000).
    for (Half& half : halves)
        if (half.foundRoom < tested + 1)
        {
            half.foundRoom = tested + tested / 4 + 64;
            half.found.reset(new Pair[half.foundRoom]); // trivial type: left uninitialised
        }
}

void GridBroadphase::fillCells(Half& half)
{
    // Item-word entries: a cell entry is the box's 4-byte item word (index and report-once
    // flags), not its edges. At 100,000 boxes the edges would be 2.8 MB written to scattered
    // places (each write a cache miss); the words are 0.7 MB, which a core's 1 MB cache holds
    // while they are written. The tests fetch each busy cell's edges from the per-item array.
    const std::size_t width = std::size_t(shape.columns);
    std::uint32_t* cursor = half.cursor.data();
    std::uint32_t* entries = cellItems.data();
    const std::uint32_t spare = start.back() + std::uint32_t(&half - halves);
    const std::uint32_t* words = cellWords.data();
    const CellFinder finder(shape);
    // From the half's last box back, each cell from its end back: every cell's boxes end up in
    // item order.
    // [slide:grid-fill]
    for (std::size_t i = half.end; i-- > half.begin;)
    {
        const std::uint32_t item = std::uint32_t(i);
        auto put = [cursor, entries, spare, item](std::size_t target, std::uint32_t covered,
                                                  std::uint32_t flags)
        {
            const std::uint32_t slot = cursor[target] -= covered;
            entries[selectWithoutBranch(covered, slot, spare)] = item | flags;
        };
        const std::uint32_t word = words[i];
        if (word != kWideBox)
            forFourCells(word & 0x3FFFFFFFu, (word >> 30) & 1u, word >> 31, width, kFirstColumnFlag,
                         kFirstRowFlag, put);
        else
            forEachCell(finder.cellsOf(edges[i]), width, kFirstColumnFlag, kFirstRowFlag, put);
    }
    // [/slide]
}

namespace
{

// Negated-max edges: a box's query is its (maxX, maxY, -minX, -minY), so that b overlaps it
// exactly when each of b's (minX, minY, -maxX, -maxY) is less: bMin < aMax, -bMax < -aMin.
// PlainPairTest is the same four comparisons in C++ (every machine); where the compiler offers
// SSE, testCellRangeFourWide makes them four-wide "less than"s.
struct PlainPairTest
{
    float maxX, maxY, negMinX, negMinY;
    explicit PlainPairTest(const float* edges) // (minX, minY, -maxX, -maxY)
        : maxX(-edges[2]), maxY(-edges[3]), negMinX(-edges[0]), negMinY(-edges[1])
    {
    }
    // Branch-free: `&` of the four comparisons, not `&&`.
    bool overlaps(const float* other) const
    {
        return (other[0] < maxX) & (other[1] < maxY) & (other[2] < negMinX) & (other[3] < negMinY);
    }
};

#if defined(HITBOX_GRID_AVX)
// What testCellsEightWide needs of the grid (it is a free function: see HITBOX_TARGET_AVX).
struct WideCellTest
{
    const std::uint32_t* start = nullptr;
    const std::uint32_t* items = nullptr;
    const float* itemEdges = nullptr;
    float* gathered = nullptr; // room for the largest cell + 1
    std::size_t firstCell = 0, endCell = 0;
    std::uint32_t bothFlags = 0, indexMask = 0;
};

// Eight-wide compares: the negated-max pair test on two entries per instruction (the
// query in both halves of an AVX register), so the inner loop runs half as often, and its end,
// which the CPU guesses wrong about once per entry, comes up half as often. The second entry
// of the last step may be one past the cell: its answer is masked off (`q + 1 < end`).
HITBOX_TARGET_AVX std::size_t testCellsEightWide(const WideCellTest& test, Pair* out)
{
    const std::uint32_t* items = test.items;
    const std::uint32_t both = test.bothFlags;
    const std::uint32_t mask = test.indexMask;
    std::uint32_t fetched = test.start[test.firstCell];
    const std::uint32_t lastEntry = test.start[test.endCell];
    const __m128 signs = _mm_set1_ps(-0.f);
    std::size_t found = 0;
    for (std::size_t cell = test.firstCell; cell < test.endCell; ++cell)
    {
        const std::uint32_t begin = test.start[cell];
        const std::uint32_t end = test.start[cell + 1];
        if (end - begin < 2)
            continue;
        const float* boxes = test.gathered;
        const std::uint32_t until = std::min(end + kFetchAhead, lastEntry);
        for (fetched = std::max(fetched, end); fetched < until; ++fetched)
            platform::prefetch(test.itemEdges + 4 * std::size_t(items[fetched] & mask));
        for (std::uint32_t p = begin; p < end; ++p)
            _mm_store_ps(test.gathered + 4 * std::size_t(p - begin),
                         _mm_load_ps(test.itemEdges + 4 * std::size_t(items[p] & mask)));
        for (std::uint32_t p = begin; p + 1 < end; ++p)
        {
            const std::uint32_t a = items[p];
            const std::uint32_t first = a & mask;
            const __m128 negated = _mm_xor_ps(_mm_load_ps(boxes + 4 * (p - begin)), signs);
            const __m128 query = _mm_shuffle_ps(negated, negated, _MM_SHUFFLE(1, 0, 3, 2));
            const __m256 queries = _mm256_insertf128_ps(_mm256_castps128_ps256(query), query, 1);
            for (std::uint32_t q = p + 1; q < end; q += 2)
            {
                const __m256 two = _mm256_loadu_ps(boxes + 4 * (q - begin));
                const int lanes = _mm256_movemask_ps(_mm256_cmp_ps(two, queries, _CMP_LT_OQ));
                const std::uint32_t b0 = items[q];
                const std::uint32_t b1 = items[q + 1];
                // Branch-free: `&`, not `&&`.
                const bool hit0 = ((lanes & 0xF) == 0xF) & (((a | b0) & both) == both);
                const bool hit1 =
                    ((lanes >> 4) == 0xF) & (((a | b1) & both) == both) & (q + 1 < end);
                out[found] = {first, b0 & mask};
                found += hit0;
                out[found] = {first, b1 & mask};
                found += hit1;
            }
        }
    }
    return found;
}

// Whether this CPU runs AVX instructions (and the system saves its registers).
bool cpuHasAvx()
{
#if defined(_MSC_VER) && !defined(__clang__)
    int info[4] = {};
    __cpuid(info, 1);
    const bool osSaves = (info[2] & (1 << 27)) != 0;
    const bool avx = (info[2] & (1 << 28)) != 0;
    return osSaves && avx && (_xgetbv(0) & 6) == 6;
#else
    return __builtin_cpu_supports("avx") != 0;
#endif
}
#endif

} // namespace

std::size_t GridBroadphase::testCellRangePlain(Half& half, Pair* out) const
{
    const std::uint32_t* items = cellItems.data();
    const Edges* itemEdges = edges.data();
    half.gathered.resize(largestCell);
    Edges* boxes = half.gathered.data();
    std::size_t found = 0;
    auto testCell = [&](std::uint32_t begin, std::uint32_t end)
    {
        // The cell's edges copied into a small array first, so the inner loop reads them from
        // the nearest cache; boxes[p - begin] is entry p's edges.
        for (std::uint32_t p = begin; p < end; ++p)
            boxes[p - begin] = itemEdges[items[p] & kItemIndexMask];
        // [slide:grid-test]
        for (std::uint32_t p = begin; p + 1 < end; ++p)
        {
            const std::uint32_t a = items[p];
            const std::uint32_t first = a & kItemIndexMask;
            const PlainPairTest test(&boxes[p - begin].minX);
            for (std::uint32_t q = p + 1; q < end; ++q)
            {
                const bool overlap = test.overlaps(&boxes[q - begin].minX);
                // Each pair once: only the top-left cell two boxes share reports them.
                const std::uint32_t b = items[q];
                const bool reportHere = ((a | b) & kBothFlags) == kBothFlags;
                // Branch-free append: always write the pair, move past it only on a hit.
                out[found] = {first, b & kItemIndexMask};
                found += reportHere & overlap;
            }
        }
        // [/slide]
    };
    forEachBusyCell(start.data(), items, itemEdges, kItemIndexMask, half.firstCell, half.endCell,
                    testCell);
    return found;
}

#if defined(HITBOX_GRID_SSE)
std::size_t GridBroadphase::testCellRangeFourWide(Half& half, Pair* out) const
{
    // Four at a time: a busy cell is copied into five columns (minX, minY, -maxX, -maxY and
    // the item word of every entry), so one box's query is compared with four other boxes in
    // four SSE "less than"s, and the report-once flags of the four are checked in two integer
    // steps. Three pad entries after the cell (minX = +infinity, overlapping nothing) let the
    // last step of four run past the cell's end without a mask. The pairs are written without
    // a branch as before (always written, the position moved on a hit), in the same order as
    // the one-at-a-time loop: by first entry, then second.
    const std::uint32_t* items = cellItems.data();
    const Edges* itemEdges = edges.data();
    const std::size_t room = std::size_t(largestCell) + 4;
    half.laneEdges.resize(4 * room);
    half.laneWords.resize(room);
    float* const minXs = half.laneEdges.data();
    float* const minYs = minXs + room;
    float* const negMaxXs = minYs + room;
    float* const negMaxYs = negMaxXs + room;
    std::uint32_t* const words = half.laneWords.data();
    const float inf = std::numeric_limits<float>::infinity();
    const __m128i indexMask = _mm_set1_epi32(int(kItemIndexMask));
    std::size_t found = 0;
    const __m128 signs = _mm_set1_ps(-0.f);
    auto testCell = [&](std::uint32_t begin, std::uint32_t end)
    {
        const std::uint32_t n = end - begin;
        if (n < kFourAtATimeFrom)
        {
            // A cell of a few boxes: each pair on its own, straight from the per-item edges
            // (copying them into columns would cost more than the few tests).
            for (std::uint32_t p = begin; p + 1 < end; ++p)
            {
                const std::uint32_t a = items[p];
                const __m128 negated =
                    _mm_xor_ps(_mm_load_ps(&itemEdges[a & kItemIndexMask].minX), signs);
                const __m128 query = _mm_shuffle_ps(negated, negated, _MM_SHUFFLE(1, 0, 3, 2));
                for (std::uint32_t q = p + 1; q < end; ++q)
                {
                    const std::uint32_t b = items[q];
                    const bool overlap =
                        _mm_movemask_ps(_mm_cmplt_ps(
                            _mm_load_ps(&itemEdges[b & kItemIndexMask].minX), query)) == 0xF;
                    const bool reportHere = ((a | b) & kBothFlags) == kBothFlags;
                    out[found] = {a & kItemIndexMask, b & kItemIndexMask};
                    found += reportHere & overlap;
                }
            }
            return;
        }
        std::uint32_t j = 0;
        // Transposed copy: four entries' edges are four rows; one 4 x 4 transpose (SSE
        // shuffles) turns them into four column pieces, stored four floats at a time.
        for (; j + 4 <= n; j += 4)
        {
            const std::uint32_t* const four = items + begin + j;
            __m128 r0 = _mm_load_ps(&itemEdges[four[0] & kItemIndexMask].minX);
            __m128 r1 = _mm_load_ps(&itemEdges[four[1] & kItemIndexMask].minX);
            __m128 r2 = _mm_load_ps(&itemEdges[four[2] & kItemIndexMask].minX);
            __m128 r3 = _mm_load_ps(&itemEdges[four[3] & kItemIndexMask].minX);
            _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
            _mm_storeu_ps(minXs + j, r0);
            _mm_storeu_ps(minYs + j, r1);
            _mm_storeu_ps(negMaxXs + j, r2);
            _mm_storeu_ps(negMaxYs + j, r3);
            _mm_storeu_si128(reinterpret_cast<__m128i*>(words + j),
                             _mm_loadu_si128(reinterpret_cast<const __m128i*>(four)));
        }
        for (; j < n; ++j)
        {
            const std::uint32_t word = items[begin + j];
            const Edges& box = itemEdges[word & kItemIndexMask];
            minXs[j] = box.minX;
            minYs[j] = box.minY;
            negMaxXs[j] = box.negMaxX;
            negMaxYs[j] = box.negMaxY;
            words[j] = word;
        }
        for (std::uint32_t j = n; j < n + 3; ++j)
        {
            minXs[j] = inf; // inf < x is false for every x: no pair with a pad
            words[j] = 0;
        }
        for (std::uint32_t p = 0; p + 1 < n; ++p)
        {
            // Box p's query (maxX, maxY, -minX, -minY), each in all four lanes (negated-max
            // edges: negating is exact, so the same answer as boxVsBox).
            const __m128 maxX = _mm_set1_ps(-negMaxXs[p]);
            const __m128 maxY = _mm_set1_ps(-negMaxYs[p]);
            const __m128 negMinX = _mm_set1_ps(-minXs[p]);
            const __m128 negMinY = _mm_set1_ps(-minYs[p]);
            const std::uint32_t a = words[p];
            // Report-once: ((a | b) & both) == both is (b & needs) == needs.
            const __m128i needs = _mm_set1_epi32(int(kBothFlags & ~a));
            const __m128i first = _mm_set1_epi32(int(a & kItemIndexMask));
            for (std::uint32_t q = p + 1; q < n; q += 4)
            {
                const __m128 onX = _mm_and_ps(_mm_cmplt_ps(_mm_loadu_ps(minXs + q), maxX),
                                              _mm_cmplt_ps(_mm_loadu_ps(negMaxXs + q), negMinX));
                const __m128 onY = _mm_and_ps(_mm_cmplt_ps(_mm_loadu_ps(minYs + q), maxY),
                                              _mm_cmplt_ps(_mm_loadu_ps(negMaxYs + q), negMinY));
                const __m128i others = _mm_loadu_si128(reinterpret_cast<const __m128i*>(words + q));
                const __m128i here = _mm_cmpeq_epi32(_mm_and_si128(others, needs), needs);
                const int hits =
                    _mm_movemask_ps(_mm_and_ps(_mm_and_ps(onX, onY), _mm_castsi128_ps(here)));
                // (first, second) of the four pairs, two per register, as Pair lays them out.
                const __m128i seconds = _mm_and_si128(others, indexMask);
                const __m128i low = _mm_unpacklo_epi32(first, seconds);
                const __m128i high = _mm_unpackhi_epi32(first, seconds);
                // Counted places: each pair's place from a table, one addition per step.
                const std::uint32_t places = kHitPlaces[hits];
                Pair* const at = out + found;
                _mm_storel_epi64(reinterpret_cast<__m128i*>(at), low);
                _mm_storeh_pd(reinterpret_cast<double*>(at + (places & 3u)), _mm_castsi128_pd(low));
                _mm_storel_epi64(reinterpret_cast<__m128i*>(at + ((places >> 2) & 3u)), high);
                _mm_storeh_pd(reinterpret_cast<double*>(at + ((places >> 4) & 3u)),
                              _mm_castsi128_pd(high));
                found += places >> 6;
            }
        }
    };
    forEachBusyCell(start.data(), items, itemEdges, kItemIndexMask, half.firstCell, half.endCell,
                    testCell);
    return found;
}
#endif

void GridBroadphase::testCells(Half& half)
{
    Pair* out = half.found.get(); // sized by startCells
    const bool eightWide = gridSettings.simd && gridSettings.eightWide && hasAvx;
#if defined(HITBOX_GRID_AVX)
    if (eightWide)
    {
        WideCellTest test;
        test.start = start.data();
        test.items = cellItems.data();
        test.itemEdges = &edges.data()->minX;
        half.gathered.resize(std::size_t(largestCell) + 1); // + 1: the pair loop reads one past
        test.gathered = &half.gathered.data()->minX;
        test.firstCell = half.firstCell;
        test.endCell = half.endCell;
        test.bothFlags = kBothFlags;
        test.indexMask = kItemIndexMask;
        half.foundCount = testCellsEightWide(test, out);
        return;
    }
#else
    (void)eightWide; // never true where AVX is not compiled (hasAvx stays false)
#endif
#if defined(HITBOX_GRID_SSE)
    if (gridSettings.simd)
    {
        half.foundCount = testCellRangeFourWide(half, out);
        return;
    }
#endif
    half.foundCount = testCellRangePlain(half, out);
}

void GridBroadphase::gatherPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs)
{
    std::vector<Pair>& gathered = gridSettings.order == PairOrder::Sorted ? cellOrderPairs : pairs;
    const Pair* first = halves[0].found.get();
    const Pair* second = halves[1].found.get();
    gathered.assign(first, first + halves[0].foundCount);
    gathered.insert(gathered.end(), second, second + halves[1].foundCount);
    // Layers rarely forbid anything (every mask all ones): then skip this pass entirely.
    if (halves[0].anyRules || halves[1].anyRules)
    {
        std::size_t kept = 0;
        for (const Pair& pair : gathered)
        {
            const BroadphaseItem& a = items[pair.first];
            const BroadphaseItem& b = items[pair.second];
            gathered[kept] = pair;
            kept += layersAllow(a.layer, a.mask, b.layer, b.mask);
        }
        gathered.resize(kept);
    }
    if (gridSettings.order == PairOrder::Sorted)
        sortPairs(pairs);
}

void GridBroadphase::sortPairs(std::vector<Pair>& pairs)
{
    // Cells find pairs in space order; Sorted promises (first, second) order. A counting sort
    // by `first` is one pass over the pairs (std::sort needs about 17 at 100,000 pairs); pairs
    // with the same first come from different cells only when a box covers several cells, so
    // those few are put in order by insertion sort.
    const std::size_t count = itemCount;
    const std::size_t pairCount = cellOrderPairs.size();
    pairStart.assign(count + 1, 0);
    const Pair* cellPairs = cellOrderPairs.data();
    for (std::size_t k = 0; k < pairCount; ++k)
        ++pairStart[cellPairs[k].first + 1];
    for (std::size_t i = 0; i < count; ++i)
        pairStart[i + 1] += pairStart[i];
    pairs.resize(pairCount);
    for (std::size_t k = 0; k < pairCount; ++k)
        pairs[pairStart[cellPairs[k].first]++] =
            cellPairs[k]; // afterwards pairStart[i] = end of i's pairs
    // Now in order of `first`; the pairs of one box are mostly in order of `second` too. One
    // insertion sort over all the pairs fixes the few that are not: a pass over the pairs
    // whose "in order?" test is almost always yes.
    // Pair key: (first, second) packed into one 64-bit number, so one comparison orders both.
    auto key = [](const Pair& pair)
    { return std::uint64_t(pair.first) << 32 | std::uint64_t(pair.second); };
    Pair* sorted = pairs.data();
    for (std::size_t k = 1; k < pairCount; ++k)
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

GridBroadphase::~GridBroadphase() = default;

SecondThread* GridBroadphase::helperThread()
{
    if (!secondThread)
    {
        try
        {
            secondThread = std::make_unique<SecondThread>();
        }
        catch (const std::system_error&)
        {
            return nullptr; // no thread to be had: this frame runs both halves itself
        }
    }
    return secondThread.get();
}

void GridBroadphase::findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs)
{
    const std::size_t count = items.size();
    itemCount = count;
    currentItems = items.data();
    edges.resize(count);
    cellWords.resize(count);
    // Always the same two halves, so the sums (and so the grid) do not depend on the threads.
    halves[0].begin = 0;
    halves[0].end = count / 2;
    halves[1].begin = count / 2;
    halves[1].end = count;
    const bool twoThreads = gridSettings.threads >= 2 && count >= gridSettings.twoThreadsFromItems;
    SecondThread* const helper = twoThreads ? helperThread() : nullptr;
    double extra = runHalves(helper, [this](int h) { prepare(halves[h]); });
    const Shape ideal = idealShape(count);
    if (!keepsShape(ideal, count))
    {
        shape = ideal;
        hasShape = true;
        extra += runHalves(helper, [this](int h) { countCells(halves[h]); });
    }
    startCells();
    extra += runHalves(helper, [this](int h) { fillCells(halves[h]); });
    extra += runHalves(helper, [this](int h) { testCells(halves[h]); });
    gatherPairs(items, pairs);
    workerExtraSeconds = extra;
    currentItems = nullptr;
    lastStats.pairsFound = pairs.size();
}

BroadphaseLayout GridBroadphase::layout() const
{
    BroadphaseLayout result;
    const std::size_t cellCount = std::size_t(shape.columns) * std::size_t(shape.rows);
    if (!hasShape || start.size() != cellCount + 1)
        return result; // no findPairs yet
    result.gridOrigin = {shape.originX, shape.originY};
    result.cellSize = shape.cell;
    result.averageSide = static_cast<float>(averageSideOfLastFrame());
    result.columns = shape.columns;
    result.rows = shape.rows;
    result.boxesPerCell.resize(cellCount);
    for (std::size_t c = 0; c < cellCount; ++c)
        result.boxesPerCell[c] = start[c + 1] - start[c];
    return result;
}

} // namespace hitbox
