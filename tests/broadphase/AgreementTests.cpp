// Every broadphase must report exactly the pairs brute force reports: same pairs, each once,
// in (first, second) order (a grid set to PairOrder::CellOrder: the same pairs in any order).
// Thousands of seeded scenes, each run for several frames with the same broadphase objects, so
// memory reuse and last frame's order are exercised too. More scenes: HITBOX_BROADPHASE_SCENES=5000
// (the `long` ctest label does this).
#include "BroadphasePrinters.h"
#include "Scenes.h"
#include "support/Printers.h"

#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/broadphase/GridBroadphase.h"
#include "hitbox/broadphase/QuadtreeBroadphase.h"
#include "hitbox/platform/Platform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>
#include <sstream>

using hitbox::Broadphase;
using hitbox::BroadphaseItem;
using hitbox::Pair;

namespace
{

std::size_t scenesPerKind()
{
    const std::optional<std::string> fromEnvironment =
        hitbox::platform::environmentVariable("HITBOX_BROADPHASE_SCENES");
    return fromEnvironment ? std::strtoul(fromEnvironment->c_str(), nullptr, 10) : 400;
}

// The four methods with their defaults, plus settings that stress them: grid cells exactly
// on the scenes' 8-pixel lattice, cells far smaller than the boxes, one giant cell; quadtrees
// that split down to single boxes, and a shallow one.
std::vector<std::unique_ptr<Broadphase>> everyMethod()
{
    std::vector<std::unique_ptr<Broadphase>> methods;
    methods.push_back(hitbox::makeBroadphase(hitbox::BroadphaseMethod::BruteForce));
    methods.push_back(hitbox::makeBroadphase(hitbox::BroadphaseMethod::SortAndSweep));
    methods.push_back(hitbox::makeBroadphase(hitbox::BroadphaseMethod::Grid));
    methods.push_back(hitbox::makeBroadphase(hitbox::BroadphaseMethod::Quadtree));
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(8.f));
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(3.f));
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(1e6f));
    methods.push_back(std::make_unique<hitbox::QuadtreeBroadphase>(1, 12));
    methods.push_back(std::make_unique<hitbox::QuadtreeBroadphase>(2, 3));
    // The grid's other settings: pairs in cell order, and two threads even on small scenes.
    hitbox::GridSettings cellOrder;
    cellOrder.order = hitbox::PairOrder::CellOrder;
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(cellOrder));
    hitbox::GridSettings twoThreads = cellOrder;
    twoThreads.threads = 2;
    twoThreads.twoThreadsFromItems = 0;
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(twoThreads));
    hitbox::GridSettings sortedTwoThreads = twoThreads;
    sortedTwoThreads.order = hitbox::PairOrder::Sorted;
    sortedTwoThreads.cellSize = 8.f;
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(sortedTwoThreads));
    // The plain C++ steps ARM and 32-bit x86 run, here run on this machine too.
    hitbox::GridSettings plain = twoThreads;
    plain.simd = false;
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(plain));
    hitbox::GridSettings plainSorted;
    plainSorted.simd = false;
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(plainSorted));
    // Two entries per compare (AVX; on CPUs without it, the same as four-wide SSE).
    hitbox::GridSettings eightWide = twoThreads;
    eightWide.eightWide = true;
    methods.push_back(std::make_unique<hitbox::GridBroadphase>(eightWide));
    return methods;
}

// The pairs in (first, second) order when `method` promises another order (a grid set to
// PairOrder::CellOrder); otherwise as they came, so their order is checked too.
std::vector<Pair> inPromisedOrder(const Broadphase& method, std::vector<Pair> pairs)
{
    const auto* grid = dynamic_cast<const hitbox::GridBroadphase*>(&method);
    if (grid != nullptr && grid->settings().order == hitbox::PairOrder::CellOrder)
        std::sort(pairs.begin(), pairs.end(),
                  [](const Pair& a, const Pair& b)
                  { return a.first != b.first ? a.first < b.first : a.second < b.second; });
    return pairs;
}

std::string describeBox(const BroadphaseItem& item)
{
    std::ostringstream text;
    hitbox::PrintTo(item.box, &text);
    text << " layer=" << item.layer << " mask=" << item.mask;
    return text.str();
}

// Empty when they agree; otherwise the first difference, with both boxes.
std::string firstDifference(const std::vector<Pair>& expected, const std::vector<Pair>& actual,
                            const std::vector<BroadphaseItem>& items)
{
    const std::size_t common = std::min(expected.size(), actual.size());
    for (std::size_t k = 0; k <= common; ++k)
    {
        const bool expectedEnded = k == expected.size();
        const bool actualEnded = k == actual.size();
        if (expectedEnded && actualEnded)
            return "";
        const bool same = !expectedEnded && !actualEnded && expected[k].first == actual[k].first &&
                          expected[k].second == actual[k].second;
        if (same)
            continue;
        std::ostringstream text;
        text << "pair #" << k << ": expected ";
        if (expectedEnded)
            text << "no more pairs";
        else
            text << "(" << expected[k].first << ", " << expected[k].second << ") "
                 << describeBox(items[expected[k].first]) << " / "
                 << describeBox(items[expected[k].second]);
        text << "; got ";
        if (actualEnded)
            text << "no more pairs";
        else
            text << "(" << actual[k].first << ", " << actual[k].second << ") "
                 << describeBox(items[actual[k].first]) << " / "
                 << describeBox(items[actual[k].second]);
        text << " (" << expected.size() << " expected, " << actual.size() << " found)";
        return text.str();
    }
    return "";
}

class AllMethodsAgreeWithBruteForce : public ::testing::TestWithParam<scenes::Kind>
{
};

TEST_P(AllMethodsAgreeWithBruteForce, OnSeededScenesOverSeveralFrames)
{
    const scenes::Kind kind = GetParam();
    std::vector<std::unique_ptr<Broadphase>> methods = everyMethod();
    std::vector<Pair> pairs;
    const std::size_t sceneCount = scenesPerKind();
    for (std::uint32_t seed = 0; seed < sceneCount; ++seed)
    {
        std::mt19937 random(seed * 8u + static_cast<std::uint32_t>(kind));
        // Every box in one spot means every pair overlaps: fewer boxes keep the run short.
        const std::size_t most = kind == scenes::Kind::OneSpot ? 40 : 120;
        const std::size_t count = std::uniform_int_distribution<std::size_t>(0, most)(random);
        const bool useLayers = seed % 3 == 0;
        std::vector<BroadphaseItem> items = scenes::make(kind, count, useLayers, random);
        // Frames 0-2 move a little, frame 3 teleports some boxes far away.
        for (int frame = 0; frame < 4; ++frame)
        {
            const std::vector<Pair> expected = scenes::referencePairs(items);
            for (const std::unique_ptr<Broadphase>& method : methods)
            {
                method->findPairs(items, pairs);
                const std::string difference =
                    firstDifference(expected, inPromisedOrder(*method, pairs), items);
                ASSERT_EQ(difference, "")
                    << method->name() << ", scene " << scenes::describe(kind) << " seed " << seed
                    << " frame " << frame << " (" << items.size() << " boxes)";
                ASSERT_EQ(method->stats().pairsFound, expected.size()) << method->name();
            }
            scenes::move(items, frame == 2, random);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(EveryKindOfScene, AllMethodsAgreeWithBruteForce,
                         ::testing::Values(scenes::Kind::Scattered, scenes::Kind::OnGridLines,
                                           scenes::Kind::BigAndSmall, scenes::Kind::FarAndHuge,
                                           scenes::Kind::ZeroSize, scenes::Kind::OneSpot,
                                           scenes::Kind::NegativeSize, scenes::Kind::WithNaN),
                         [](const ::testing::TestParamInfo<scenes::Kind>& info)
                         { return scenes::describe(info.param); });

TEST(AllMethodsAgreeWithBruteForce, WhileHundredsOfBoxesMoveForManyFrames)
{
    // One long run: the sort-and-sweep order and the grid's buffers carry over frame to frame,
    // boxes are added and removed, and every 25th frame some jump across the world.
    std::mt19937 random(2024);
    std::vector<std::unique_ptr<Broadphase>> methods = everyMethod();
    std::vector<BroadphaseItem> items = scenes::make(scenes::Kind::Scattered, 300, true, random);
    std::vector<Pair> pairs;
    for (int frame = 0; frame < 200; ++frame)
    {
        if (frame % 10 == 5)
            items.resize(items.size() - 20); // boxes removed
        if (frame % 10 == 0 && frame > 0)
        {
            const std::vector<BroadphaseItem> more =
                scenes::make(scenes::Kind::BigAndSmall, 25, true, random);
            items.insert(items.end(), more.begin(), more.end()); // boxes added
        }
        const std::vector<Pair> expected = scenes::referencePairs(items);
        for (const std::unique_ptr<Broadphase>& method : methods)
        {
            method->findPairs(items, pairs);
            ASSERT_EQ(firstDifference(expected, inPromisedOrder(*method, pairs), items), "")
                << method->name() << " frame " << frame;
        }
        scenes::move(items, frame % 25 == 24, random);
    }
}

} // namespace

namespace
{

TEST(GridBroadphase, AgreesWithBruteForceOnBoxesTooSmallToDivideBy)
{
    // Sides of 1e-40 (below float's normal range): one over such a cell size is infinity in
    // float, and 0 * infinity is NaN, which once turned into a cell index far outside the grid.
    std::vector<BroadphaseItem> items(3);
    items[0].box = {0.f, 0.f, 1e-40f, 1e-40f};
    items[1].box = {5e-41f, 5e-41f, 1e-40f, 1e-40f}; // overlaps box 0
    items[2].box = {1e-39f, 0.f, 1e-40f, 1e-40f};    // ten of its own widths away
    const std::vector<Pair> expected = scenes::referencePairs(items);
    ASSERT_EQ(expected.size(), 1u);
    hitbox::GridBroadphase cellFromAverageSize;
    hitbox::GridBroadphase tinyCell(1e-40f);
    std::vector<Pair> pairs;
    for (Broadphase* grid :
         {static_cast<Broadphase*>(&cellFromAverageSize), static_cast<Broadphase*>(&tinyCell)})
    {
        grid->findPairs(items, pairs);
        EXPECT_EQ(firstDifference(expected, pairs, items), "");
    }
}

} // namespace

namespace
{

// 24,000 drifting boxes, above the grid's two-thread threshold: one thread and two must give
// the same pairs in the same order (cell order and sorted), every frame, and the same pairs
// as sort and sweep, an unrelated method.
TEST(GridBroadphase, TwoThreadsGiveTheSamePairsInTheSameOrderAsOne)
{
    std::mt19937 random(31);
    std::vector<BroadphaseItem> items = scenes::make(scenes::Kind::Scattered, 24000, false, random);
    // Spread them out so each box has a few neighbours, as in a game (Scenes packs 120).
    std::uniform_real_distribution<float> where(0.f, 3100.f);
    for (BroadphaseItem& item : items)
        item.box.left = where(random), item.box.top = where(random);
    ASSERT_GE(items.size(), hitbox::kGridTwoThreadsFromItems);
    hitbox::GridSettings one;
    one.order = hitbox::PairOrder::CellOrder;
    hitbox::GridSettings two = one;
    two.threads = 2;
    hitbox::GridBroadphase oneThread(one), twoThreads(two);
    hitbox::GridSettings sortedTwo = two;
    sortedTwo.order = hitbox::PairOrder::Sorted;
    hitbox::GridBroadphase sortedTwoThreads(sortedTwo);
    hitbox::GridSettings plainOne = one; // the plain C++ steps of machines without SSE
    plainOne.simd = false;
    hitbox::GridBroadphase plainOneThread(plainOne);
    std::vector<Pair> fromPlain;
    // Four at a time (SSE) against one at a time (plain C++), both with two threads and a
    // given cell size, so both build the same grid: the same pairs in the same order.
    hitbox::GridSettings fourFixed = two;
    fourFixed.cellSize = 60.f; // about 14 boxes a cell: both the four-wide and the few-box path
    hitbox::GridSettings plainFixed = fourFixed;
    plainFixed.simd = false;
    hitbox::GridBroadphase fourFixedThreads(fourFixed), plainFixedThreads(plainFixed);
    std::vector<Pair> fromFourFixed, fromPlainFixed;
    // Two entries per compare (AVX where the CPU has it), one thread: the same order again.
    hitbox::GridSettings wideOne = one;
    wideOne.eightWide = true;
    hitbox::GridBroadphase wideOneThread(wideOne);
    std::vector<Pair> fromWide;
    auto sweep = hitbox::makeBroadphase(hitbox::BroadphaseMethod::SortAndSweep);
    std::vector<Pair> fromOne, fromTwo, sorted, expected;
    for (int frame = 0; frame < 3; ++frame)
    {
        oneThread.findPairs(items, fromOne);
        twoThreads.findPairs(items, fromTwo);
        sortedTwoThreads.findPairs(items, sorted);
        plainOneThread.findPairs(items, fromPlain);
        fourFixedThreads.findPairs(items, fromFourFixed);
        plainFixedThreads.findPairs(items, fromPlainFixed);
        wideOneThread.findPairs(items, fromWide);
        sweep->findPairs(items, expected);
        ASSERT_GT(expected.size(), 1000u) << "the scene should have many pairs";
        ASSERT_EQ(fromOne.size(), fromTwo.size()) << "frame " << frame;
        for (std::size_t k = 0; k < fromOne.size(); ++k)
            ASSERT_TRUE(fromOne[k].first == fromTwo[k].first &&
                        fromOne[k].second == fromTwo[k].second)
                << "pair #" << k << " differs, frame " << frame;
        ASSERT_GT(fromFourFixed.size(), 1000u) << "frame " << frame;
        ASSERT_EQ(fromFourFixed.size(), fromPlainFixed.size()) << "frame " << frame;
        for (std::size_t k = 0; k < fromFourFixed.size(); ++k)
            ASSERT_TRUE(fromFourFixed[k].first == fromPlainFixed[k].first &&
                        fromFourFixed[k].second == fromPlainFixed[k].second)
                << "four at a time: pair #" << k << " differs, frame " << frame;
        ASSERT_EQ(fromOne.size(), fromWide.size()) << "frame " << frame;
        for (std::size_t k = 0; k < fromOne.size(); ++k)
            ASSERT_TRUE(fromOne[k].first == fromWide[k].first &&
                        fromOne[k].second == fromWide[k].second)
                << "eight-wide: pair #" << k << " differs, frame " << frame;
        EXPECT_EQ(firstDifference(expected, inPromisedOrder(oneThread, fromOne), items), "");
        EXPECT_EQ(firstDifference(expected, sorted, items), "");
        // (As sets: the two sum the boxes' sizes in another order, so their grids may differ.)
        EXPECT_EQ(firstDifference(inPromisedOrder(oneThread, fromOne),
                                  inPromisedOrder(plainOneThread, fromPlain), items),
                  "")
            << "SSE and plain C++ differ";
        EXPECT_EQ(oneThread.stats().pairsTested, twoThreads.stats().pairsTested);
        scenes::move(items, frame == 1, random);
    }
}

} // namespace
