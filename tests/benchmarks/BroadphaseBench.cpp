// broadphase_bench - one frame of N moving boxes: move every box, then report every
// overlapping pair. Benchmarks are named <Method>/<N>. Counters:
//   pairs       - pairs found in the first frame (every method must show the same number)
//   ns_per_box  - frame time / N: flat across N means the method scales linearly
// Box2DTree/<N> is Box2D 2.4.1's b2DynamicTree used the way a Box2D user would: one proxy per
// box, MoveProxy every frame, then Query each box's AABB and keep each overlapping pair once.
// BaselineGrid/<N> is the grid as it was before issue 31 (BaselineGrid.h), kept so the new
// grid's speed-up is a ratio measured in the same run. Grid/<N> is today's grid as the World
// uses it (pairs sorted, one thread), GridCellOrder/<N> leaves the pairs in cell order and
// GridEightWide/<N> is GridCellOrder with two entries per compare (AVX, where the CPU has it)
// instead of four-wide SSE steps, GridTwoThreads/<N> also splits the work over two threads (its CPU
// time counts both threads; its wall time is the "Time" column). Before timing, each grid's pairs
// are checked against the baseline's, as a set: a benchmark whose pairs differ stops with an error.
// GridCellOrderVsBaseline/<N> runs both on every frame, in turn (which goes first alternates),
// each timed on its own: a paired measurement, so a slow minute of the host slows both sides
// of the ratio alike. Its counters: baseline_ns_per_box, grid_ns_per_box and ratio (grid /
// baseline, issue 31's criterion 1).
// Results, machine and the exact command: docs/performance.md.
#include "BaselineGrid.h"
#include "MovingBoxes.h"

#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/broadphase/GridBroadphase.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <memory>
#include <vector>

#ifdef HITBOX_HAVE_BOX2D
#include <box2d/b2_dynamic_tree.h>
#endif

namespace
{

constexpr unsigned kSeed = 42;

// Measures the frames' CPU time (like the CPU column), so a busy machine (other programs on
// the same cores) disturbs ns_per_box less than wall-clock time would.
class FrameClock
{
public:
    FrameClock() : start(std::clock()) {}
    // `pairs`: the pairs of the first timed frame, the same frame for every method.
    void report(benchmark::State& state, std::size_t boxes, std::size_t pairs) const
    {
        const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
        const double frames = static_cast<double>(state.iterations());
        state.counters["pairs"] = static_cast<double>(pairs);
        state.counters["ns_per_box"] = seconds * 1e9 / (frames * static_cast<double>(boxes));
    }

private:
    std::clock_t start;
};

// The pairs as a set: sorted, so two lists in different orders compare equal.
std::vector<std::uint64_t> asSet(const std::vector<hitbox::Pair>& pairs)
{
    std::vector<std::uint64_t> keys;
    keys.reserve(pairs.size());
    for (const hitbox::Pair& pair : pairs)
        keys.push_back(std::uint64_t(pair.first) << 32 | pair.second);
    std::sort(keys.begin(), keys.end());
    return keys;
}

void runBroadphase(benchmark::State& state, std::unique_ptr<hitbox::Broadphase> broadphase)
{
    const std::size_t count = static_cast<std::size_t>(state.range(0));
    MovingBoxes boxes(count, kSeed);
    std::vector<hitbox::Pair> pairs;
    broadphase->findPairs(boxes.items, pairs); // warm up: buffers reach their size
    {
        // Same pairs as the baseline grid, three frames in a row (the grid keeps state).
        MovingBoxes check(count, kSeed + 1);
        bench::BaselineGrid baseline;
        std::vector<hitbox::Pair> expected;
        for (int frame = 0; frame < 3; ++frame)
        {
            check.step();
            baseline.findPairs(check.items, expected);
            broadphase->findPairs(check.items, pairs);
            if (asSet(pairs) != asSet(expected))
            {
                state.SkipWithError("pairs differ from BaselineGrid's");
                return;
            }
        }
        broadphase->findPairs(boxes.items, pairs);
    }
    std::size_t firstFramePairs = 0;
    FrameClock clock;
    for (auto _ : state)
    {
        boxes.step();
        broadphase->findPairs(boxes.items, pairs);
        if (firstFramePairs == 0)
            firstFramePairs = pairs.size();
        benchmark::DoNotOptimize(pairs.data());
        benchmark::ClobberMemory();
    }
    clock.report(state, count, firstFramePairs);
}

void BruteForce(benchmark::State& state)
{
    runBroadphase(state, hitbox::makeBroadphase(hitbox::BroadphaseMethod::BruteForce));
}
void SortAndSweep(benchmark::State& state)
{
    runBroadphase(state, hitbox::makeBroadphase(hitbox::BroadphaseMethod::SortAndSweep));
}
void BaselineGrid(benchmark::State& state)
{
    runBroadphase(state, std::make_unique<bench::BaselineGrid>());
}
void Grid(benchmark::State& state)
{
    runBroadphase(state, hitbox::makeBroadphase(hitbox::BroadphaseMethod::Grid));
}
void GridCellOrder(benchmark::State& state)
{
    hitbox::GridSettings settings;
    settings.order = hitbox::PairOrder::CellOrder;
    runBroadphase(state, std::make_unique<hitbox::GridBroadphase>(settings));
}
void GridEightWide(benchmark::State& state)
{
    hitbox::GridSettings settings;
    settings.order = hitbox::PairOrder::CellOrder;
    settings.eightWide = true;
    runBroadphase(state, std::make_unique<hitbox::GridBroadphase>(settings));
}
void GridTwoThreads(benchmark::State& state)
{
    hitbox::GridSettings settings;
    settings.order = hitbox::PairOrder::CellOrder;
    settings.threads = 2;
    runBroadphase(state, std::make_unique<hitbox::GridBroadphase>(settings));
}
// Both grids on the same frames, each timed alone by a steady clock (a thread CPU clock ticks
// too coarsely on Windows for one frame): the ratio of two sums of per-frame times taken side
// by side (a paired design: host noise lands on both in the same minute).
void GridCellOrderVsBaseline(benchmark::State& state)
{
    using Clock = std::chrono::steady_clock;
    const std::size_t count = static_cast<std::size_t>(state.range(0));
    MovingBoxes boxes(count, kSeed);
    bench::BaselineGrid baseline;
    hitbox::GridSettings settings;
    settings.order = hitbox::PairOrder::CellOrder;
    hitbox::GridBroadphase grid(settings);
    std::vector<hitbox::Pair> baselinePairs;
    std::vector<hitbox::Pair> gridPairs;
    for (int frame = 0; frame < 3; ++frame) // warm up, and the same pairs before timing
    {
        boxes.step();
        baseline.findPairs(boxes.items, baselinePairs);
        grid.findPairs(boxes.items, gridPairs);
        if (asSet(gridPairs) != asSet(baselinePairs))
        {
            state.SkipWithError("pairs differ from BaselineGrid's");
            return;
        }
    }
    Clock::duration baselineTime{};
    Clock::duration gridTime{};
    bool baselineFirst = true;
    for (auto _ : state)
    {
        boxes.step();
        for (int turn = 0; turn < 2; ++turn)
        {
            const bool runBaseline = (turn == 0) == baselineFirst;
            const Clock::time_point start = Clock::now();
            if (runBaseline)
                baseline.findPairs(boxes.items, baselinePairs);
            else
                grid.findPairs(boxes.items, gridPairs);
            (runBaseline ? baselineTime : gridTime) += Clock::now() - start;
        }
        baselineFirst = !baselineFirst;
        benchmark::DoNotOptimize(baselinePairs.data());
        benchmark::DoNotOptimize(gridPairs.data());
        benchmark::ClobberMemory();
    }
    const double boxFrames = static_cast<double>(state.iterations()) * static_cast<double>(count);
    const double baselineNs = std::chrono::duration<double, std::nano>(baselineTime).count();
    const double gridNs = std::chrono::duration<double, std::nano>(gridTime).count();
    state.counters["baseline_ns_per_box"] = baselineNs / boxFrames;
    state.counters["grid_ns_per_box"] = gridNs / boxFrames;
    state.counters["ratio"] = baselineNs > 0.0 ? gridNs / baselineNs : 0.0;
}
void Quadtree(benchmark::State& state)
{
    runBroadphase(state, hitbox::makeBroadphase(hitbox::BroadphaseMethod::Quadtree));
}

#ifdef HITBOX_HAVE_BOX2D

b2AABB toAabb(const hitbox::Box& box)
{
    b2AABB aabb;
    aabb.lowerBound.Set(box.left, box.top);
    aabb.upperBound.Set(box.left + box.width, box.top + box.height);
    return aabb;
}

// Box2D's Query calls QueryCallback(proxyId) for every proxy whose fat AABB overlaps.
struct PairCollector
{
    const b2DynamicTree* tree = nullptr;
    const MovingBoxes* boxes = nullptr;
    std::uint32_t queried = 0;
    std::vector<hitbox::Pair>* pairs = nullptr;

    bool QueryCallback(std::int32_t proxyId)
    {
        const auto other = static_cast<std::uint32_t>(
            reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxyId)));
        if (other <= queried)
            return true; // each pair once: the lower index reports it
        // The tree's boxes are fattened: test the real boxes with Hitbox's edge rule.
        const hitbox::Box& a = boxes->items[queried].box;
        const hitbox::Box& b = boxes->items[other].box;
        if (a.left < b.left + b.width && b.left < a.left + a.width && a.top < b.top + b.height &&
            b.top < a.top + a.height)
            pairs->push_back({queried, other});
        return true;
    }
};

void Box2DTree(benchmark::State& state)
{
    const std::size_t count = static_cast<std::size_t>(state.range(0));
    MovingBoxes boxes(count, kSeed);
    b2DynamicTree tree;
    std::vector<std::int32_t> proxies(count);
    for (std::size_t i = 0; i < count; ++i)
        proxies[i] = tree.CreateProxy(toAabb(boxes.items[i].box),
                                      reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    std::vector<hitbox::Pair> pairs;
    PairCollector collector{&tree, &boxes, 0, &pairs};
    std::size_t firstFramePairs = 0;
    FrameClock clock;
    for (auto _ : state)
    {
        boxes.step();
        for (std::size_t i = 0; i < count; ++i)
        {
            const b2Vec2 move(boxes.lastMove[i].x, boxes.lastMove[i].y);
            tree.MoveProxy(proxies[i], toAabb(boxes.items[i].box), move);
        }
        pairs.clear();
        for (std::size_t i = 0; i < count; ++i)
        {
            collector.queried = static_cast<std::uint32_t>(i);
            tree.Query(&collector, toAabb(boxes.items[i].box));
        }
        if (firstFramePairs == 0)
            firstFramePairs = pairs.size();
        benchmark::DoNotOptimize(pairs.data());
        benchmark::ClobberMemory();
    }
    clock.report(state, count, firstFramePairs);
}

#endif

void sizes(benchmark::internal::Benchmark* benchmark)
{
    benchmark->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
}

} // namespace

BENCHMARK(BaselineGrid)->Apply(sizes);
BENCHMARK(Grid)->Apply(sizes);
BENCHMARK(GridCellOrder)->Apply(sizes);
BENCHMARK(GridCellOrderVsBaseline)->Apply(sizes);
BENCHMARK(GridEightWide)->Apply(sizes);
BENCHMARK(GridTwoThreads)->Apply(sizes);
BENCHMARK(SortAndSweep)->Apply(sizes);
BENCHMARK(Quadtree)->Apply(sizes);
#ifdef HITBOX_HAVE_BOX2D
BENCHMARK(Box2DTree)->Apply(sizes);
#endif
// 100,000 boxes by brute force is 5 billion tests: one frame is enough to make the point.
BENCHMARK(BruteForce)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BruteForce)->Arg(100000)->Iterations(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
