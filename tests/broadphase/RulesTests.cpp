// The broadphase rules one at a time, for every method: the edge rule, degenerate boxes,
// layers and masks, the order of the pairs, and the statistics the lab shows.
#include "BroadphasePrinters.h"
#include "support/Printers.h"

#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/broadphase/GridBroadphase.h"
#include "hitbox/broadphase/GridCellRule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using hitbox::BroadphaseItem;
using hitbox::BroadphaseMethod;
using hitbox::Pair;

namespace
{

const BroadphaseMethod allMethods[] = {BroadphaseMethod::BruteForce, BroadphaseMethod::SortAndSweep,
                                       BroadphaseMethod::Grid, BroadphaseMethod::Quadtree};

std::vector<std::pair<std::uint32_t, std::uint32_t>>
pairsFound(BroadphaseMethod method, const std::vector<BroadphaseItem>& items)
{
    std::vector<Pair> pairs;
    hitbox::makeBroadphase(method)->findPairs(items, pairs);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> result;
    for (const Pair& pair : pairs)
        result.emplace_back(pair.first, pair.second);
    return result;
}

using PairList = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

class EveryBroadphase : public ::testing::TestWithParam<BroadphaseMethod>
{
};

TEST_P(EveryBroadphase, OverlappingBoxesPairOnce)
{
    const std::vector<BroadphaseItem> items = {{{0.f, 0.f, 10.f, 10.f}}, {{5.f, 5.f, 10.f, 10.f}}};
    EXPECT_EQ(pairsFound(GetParam(), items), (PairList{{0, 1}}));
}

TEST_P(EveryBroadphase, TouchingEdgesAndCornersDoNotPair)
{
    const std::vector<BroadphaseItem> items = {{{0.f, 0.f, 10.f, 10.f}},
                                               {{10.f, 0.f, 10.f, 10.f}},    // right edge
                                               {{0.f, 10.f, 10.f, 10.f}},    // bottom edge
                                               {{-10.f, -10.f, 10.f, 10.f}}, // corner
                                               {{-10.f, 0.f, 10.f, 10.f}},   // left edge
                                               {{0.f, -10.f, 10.f, 10.f}}};  // top edge
    EXPECT_EQ(pairsFound(GetParam(), items), PairList{});
}

TEST_P(EveryBroadphase, FarApartBoxesDoNotPair)
{
    const std::vector<BroadphaseItem> items = {{{0.f, 0.f, 10.f, 10.f}},
                                               {{500.f, 300.f, 10.f, 10.f}}};
    EXPECT_EQ(pairsFound(GetParam(), items), PairList{});
}

TEST_P(EveryBroadphase, PairsComeSortedByFirstThenSecond)
{
    // Item 3 is big and overlaps everything; the others overlap only it.
    const std::vector<BroadphaseItem> items = {{{300.f, 300.f, 10.f, 10.f}},
                                               {{0.f, 0.f, 10.f, 10.f}},
                                               {{150.f, 150.f, 10.f, 10.f}},
                                               {{-5.f, -5.f, 400.f, 400.f}}};
    EXPECT_EQ(pairsFound(GetParam(), items), (PairList{{0, 3}, {1, 3}, {2, 3}}));
}

TEST_P(EveryBroadphase, AZeroSizeBoxPairsOnlyWhenStrictlyInside)
{
    const std::vector<BroadphaseItem> items = {{{0.f, 0.f, 10.f, 10.f}},
                                               {{5.f, 5.f, 0.f, 0.f}},  // inside: pairs
                                               {{10.f, 5.f, 0.f, 0.f}}, // on the edge: no
                                               {{5.f, 5.f, 0.f, 0.f}}}; // same point as 1: no
    EXPECT_EQ(pairsFound(GetParam(), items), (PairList{{0, 1}, {0, 3}}));
}

TEST_P(EveryBroadphase, NegativeSizesSpanBackwards)
{
    const std::vector<BroadphaseItem> items = {{{10.f, 10.f, -10.f, -10.f}},
                                               {{5.f, 5.f, 10.f, 10.f}}};
    EXPECT_EQ(pairsFound(GetParam(), items), (PairList{{0, 1}}));
}

TEST_P(EveryBroadphase, NaNAndInfiniteBoxesNeverPair)
{
    const float notANumber = std::numeric_limits<float>::quiet_NaN();
    const float infinite = std::numeric_limits<float>::infinity();
    const std::vector<BroadphaseItem> items = {{{0.f, 0.f, 100.f, 100.f}},
                                               {{notANumber, 5.f, 10.f, 10.f}},
                                               {{5.f, 5.f, infinite, 10.f}},
                                               {{-infinite, -infinite, infinite, infinite}},
                                               {{5.f, 5.f, 10.f, notANumber}}};
    EXPECT_EQ(pairsFound(GetParam(), items), PairList{});
}

TEST_P(EveryBroadphase, EveryBoxInOneSpotPairsWithEveryOther)
{
    const std::vector<BroadphaseItem> items(5, BroadphaseItem{{40.f, 40.f, 8.f, 8.f}});
    EXPECT_EQ(
        pairsFound(GetParam(), items),
        (PairList{{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}));
}

TEST_P(EveryBroadphase, HugeAndNegativeCoordinatesWork)
{
    const std::vector<BroadphaseItem> items = {{{-1e30f, -1e30f, 2e30f, 2e30f}},
                                               {{-5e29f, 0.f, 1.f, 1.f}},
                                               {{3e38f, 3e38f, 1e37f, 1e37f}},
                                               {{3.05e38f, 3.05e38f, 1e30f, 1e30f}}};
    EXPECT_EQ(pairsFound(GetParam(), items), (PairList{{0, 1}, {2, 3}}));
}

TEST_P(EveryBroadphase, ABulletIgnoresItsOwnerAndPickupsIgnoreEachOther)
{
    const std::uint32_t player = 1, bullet = 2, enemy = 4, pickup = 8;
    const std::vector<BroadphaseItem> items = {
        {{0.f, 0.f, 20.f, 20.f}, player, enemy | pickup},
        {{5.f, 5.f, 4.f, 4.f}, bullet, enemy}, // fired by the player: ignores it
        {{10.f, 10.f, 20.f, 20.f}, enemy, player | bullet},
        {{12.f, 0.f, 6.f, 6.f}, pickup, player}, // overlaps the other pickup: ignored
        {{14.f, 2.f, 6.f, 6.f}, pickup, player}};
    EXPECT_EQ(pairsFound(GetParam(), items), (PairList{{0, 2}, {0, 3}, {0, 4}}));
}

TEST_P(EveryBroadphase, ReusesThePairsMemoryFrameAfterFrame)
{
    std::mt19937 random(7);
    std::uniform_real_distribution<float> position(0.f, 300.f);
    std::vector<BroadphaseItem> items(200);
    for (BroadphaseItem& item : items)
        item.box = {position(random), position(random), 20.f, 20.f};
    auto broadphase = hitbox::makeBroadphase(GetParam());
    std::vector<Pair> pairs;
    broadphase->findPairs(items, pairs);
    const Pair* memory = pairs.data();
    const std::size_t found = pairs.size();
    broadphase->findPairs(items, pairs);
    EXPECT_EQ(pairs.data(), memory);
    EXPECT_EQ(pairs.size(), found);
    EXPECT_EQ(broadphase->stats().pairsFound, found);
}

TEST_P(EveryBroadphase, EmptyAndSingleItemListsHaveNoPairs)
{
    EXPECT_EQ(pairsFound(GetParam(), {}), PairList{});
    EXPECT_EQ(pairsFound(GetParam(), {BroadphaseItem{{0.f, 0.f, 5.f, 5.f}}}), PairList{});
}

TEST_P(EveryBroadphase, IsNamedLikeItsMethod)
{
    EXPECT_STREQ(hitbox::makeBroadphase(GetParam())->name(), hitbox::toString(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(AllMethods, EveryBroadphase, ::testing::ValuesIn(allMethods),
                         [](const ::testing::TestParamInfo<BroadphaseMethod>& info)
                         { return std::string(hitbox::toString(info.param)); });

TEST(BroadphaseStats, BruteForceTestsEveryPairTheLayersAllow)
{
    std::vector<BroadphaseItem> items(100, BroadphaseItem{{0.f, 0.f, 1.f, 1.f}});
    for (std::size_t i = 0; i < items.size(); ++i)
        items[i].box.left = 10.f * static_cast<float>(i);
    auto bruteForce = hitbox::makeBroadphase(BroadphaseMethod::BruteForce);
    std::vector<Pair> pairs;
    bruteForce->findPairs(items, pairs);
    EXPECT_EQ(bruteForce->stats().pairsTested, 100u * 99u / 2u);
    EXPECT_EQ(bruteForce->stats().pairsFound, 0u);
}

TEST(BroadphaseStats, TheGridTestsFarFewerPairsThanBruteForceOnASpreadOutScene)
{
    std::mt19937 random(3);
    std::uniform_real_distribution<float> x(0.f, 1200.f), y(0.f, 675.f);
    std::vector<BroadphaseItem> items(1000);
    for (BroadphaseItem& item : items)
        item.box = {x(random), y(random), 10.f, 10.f};
    auto grid = hitbox::makeBroadphase(BroadphaseMethod::Grid);
    std::vector<Pair> pairs;
    grid->findPairs(items, pairs);
    EXPECT_LT(grid->stats().pairsTested, 1000u * 999u / 2u / 100u);
}

TEST(GridBroadphase, PicksACellSizeFromTheBoxesWhenNotGivenOne)
{
    // 50 boxes of 16 x 16 in a row, 40 apart: they spread over 1,976 x 16 pixels.
    std::vector<BroadphaseItem> items(50, BroadphaseItem{{0.f, 0.f, 16.f, 16.f}});
    for (std::size_t i = 0; i < items.size(); ++i)
        items[i].box.left = 40.f * static_cast<float>(i);
    hitbox::GridBroadphase grid;
    std::vector<Pair> pairs;
    grid.findPairs(items, pairs);
    const double coverage = 50.0 * 16.0 * 16.0 / (1976.0 * 16.0); // about 0.40
    EXPECT_DOUBLE_EQ(hitbox::gridCoverage(50.0, 16.0, 1976.0, 16.0), coverage);
    EXPECT_FLOAT_EQ(grid.layout().cellSize, float(hitbox::gridCellSizeFor(16.0, coverage)));
    // Sparser than crowded boxes, so a bigger cell than 3 sides; not the sparse limit, 6.
    EXPECT_GT(grid.layout().cellSize, 3.f * 16.f);
    EXPECT_LT(grid.layout().cellSize, 6.f * 16.f);
    EXPECT_FLOAT_EQ(grid.layout().averageSide, 16.f);
    hitbox::GridBroadphase fixedGrid(25.f);
    fixedGrid.findPairs(items, pairs);
    EXPECT_FLOAT_EQ(fixedGrid.layout().cellSize, 25.f);
}

TEST(GridBroadphase, CellScaleMultipliesTheRulesCellAndFindsTheSamePairs)
{
    std::mt19937 random(5);
    std::uniform_real_distribution<float> position(0.f, 500.f);
    std::uniform_real_distribution<float> side(4.f, 12.f);
    std::vector<BroadphaseItem> items(600);
    for (BroadphaseItem& item : items)
        item.box = {position(random), position(random), side(random), side(random)};
    auto asList = [](const std::vector<Pair>& pairs)
    {
        PairList list;
        for (const Pair& pair : pairs)
            list.emplace_back(pair.first, pair.second);
        return list;
    };
    hitbox::GridBroadphase ruled;
    std::vector<Pair> expected;
    ruled.findPairs(items, expected);
    const float ruleCell = ruled.layout().cellSize;
    // (Not 0.25: that grid would need more cells than kMaxCellsPerItem allows, and grows them.)
    for (float scale : {0.5f, 2.f, 4.f})
    {
        hitbox::GridSettings settings;
        settings.cellScale = scale;
        hitbox::GridBroadphase scaled(settings);
        std::vector<Pair> pairs;
        scaled.findPairs(items, pairs);
        EXPECT_FLOAT_EQ(scaled.layout().cellSize, ruleCell * scale) << "scale " << scale;
        EXPECT_EQ(asList(pairs), asList(expected)) << "scale " << scale;
    }
    // A scale that is not a positive number counts as 1; a fixed cell ignores the scale.
    for (float scale : {0.f, -2.f, std::numeric_limits<float>::quiet_NaN(),
                        std::numeric_limits<float>::infinity()})
    {
        hitbox::GridSettings settings;
        settings.cellScale = scale;
        hitbox::GridBroadphase scaled(settings);
        std::vector<Pair> pairs;
        scaled.findPairs(items, pairs);
        EXPECT_FLOAT_EQ(scaled.layout().cellSize, ruleCell) << "scale " << scale;
    }
    hitbox::GridSettings fixedCell;
    fixedCell.cellSize = 30.f;
    fixedCell.cellScale = 2.f;
    hitbox::GridBroadphase fixedGrid(fixedCell);
    fixedGrid.findPairs(items, expected);
    EXPECT_FLOAT_EQ(fixedGrid.layout().cellSize, 30.f);
}

// The cell rule's cost model (GridCellRule.h), per box, for a cell k average sides wide:
// kEntryCostInPairTests x the cells it is listed in, plus its share of the pair tests.
double cellRuleCost(double coverage, double k)
{
    return hitbox::kEntryCostInPairTests * (1.0 + 1.0 / k) * (1.0 + 1.0 / k) +
           coverage * std::pow(1.0 + k, 4.0) / (2.0 * k * k);
}

TEST(GridCellRule, CrowdedBoxesGetThreeSidesSparseOnesUpToSix)
{
    // Crowded: the benchmark's boxes (0.75) and anything denser, or boxes with no area.
    for (const double coverage : {0.75, 1.0, 40.0, std::numeric_limits<double>::infinity()})
        EXPECT_DOUBLE_EQ(hitbox::gridCellPerAverageSide(coverage), 3.0) << coverage;
    // Sparse: 6 from about 0.098 down to nothing at all.
    for (const double coverage : {0.09, 0.01, 0.0})
        EXPECT_DOUBLE_EQ(hitbox::gridCellPerAverageSide(coverage), 6.0) << coverage;
    // Lab 8's crowd: balls covering 12 % of the arena, their squares 4 / pi times that.
    EXPECT_NEAR(hitbox::gridCellPerAverageSide(0.12 * 4.0 / 3.14159265358979), 5.15, 0.01);
    // Not a number, or below nothing: the crowded rule, never a NaN cell.
    EXPECT_DOUBLE_EQ(hitbox::gridCellPerAverageSide(std::nan("")), 3.0);
    EXPECT_DOUBLE_EQ(hitbox::gridCellPerAverageSide(-1.0), 3.0);
    EXPECT_DOUBLE_EQ(hitbox::gridCellSizeFor(16.0, 0.75), 48.0);
}

TEST(GridCellRule, PicksTheCheapestCellOfTheCostModel)
{
    double previous = 6.0;
    for (int percent = 9; percent <= 80; ++percent)
    {
        const double coverage = percent / 100.0;
        const double k = hitbox::gridCellPerAverageSide(coverage);
        // Thinner boxes never get a smaller cell.
        EXPECT_LE(k, previous) << coverage;
        previous = k;
        // Within [3, 6] the model's cost is lowest at k: a little bigger or smaller costs more.
        if (k > 3.0 && k < 6.0)
        {
            EXPECT_LT(cellRuleCost(coverage, k), cellRuleCost(coverage, k - 0.05)) << coverage;
            EXPECT_LT(cellRuleCost(coverage, k), cellRuleCost(coverage, k + 0.05)) << coverage;
        }
    }
}

TEST(GridCellRule, CoverageIsTheBoxesAreaOverTheAreaTheySpreadOver)
{
    EXPECT_DOUBLE_EQ(hitbox::gridCoverage(100.0, 2.0, 20.0, 20.0), 1.0);
    EXPECT_DOUBLE_EQ(hitbox::gridCoverage(25.0, 2.0, 20.0, 20.0), 0.25);
    EXPECT_EQ(hitbox::gridCoverage(3.0, 2.0, 0.0, 20.0), std::numeric_limits<double>::infinity());
    EXPECT_DOUBLE_EQ(hitbox::gridCoverage(0.0, 2.0, 20.0, 20.0), 0.0);
    // Two negative sides are no area either (not a positive one).
    EXPECT_EQ(hitbox::gridCoverage(3.0, 2.0, -10.0, -10.0),
              std::numeric_limits<double>::infinity());
    // A NaN side stays NaN, and the rule answers it with the crowded cell.
    EXPECT_TRUE(std::isnan(hitbox::gridCoverage(3.0, std::nan(""), 20.0, 20.0)));
    EXPECT_DOUBLE_EQ(
        hitbox::gridCellPerAverageSide(hitbox::gridCoverage(3.0, std::nan(""), 20.0, 20.0)),
        hitbox::kGridCellPerAverageSideCrowded);
}

TEST(Broadphase, DrawsItsStructureForTheDebugView)
{
    std::vector<BroadphaseItem> items(20, BroadphaseItem{{0.f, 0.f, 30.f, 30.f}});
    for (std::size_t i = 0; i < items.size(); ++i)
        items[i].box.left = 20.f * static_cast<float>(i);
    for (BroadphaseMethod method :
         {BroadphaseMethod::SortAndSweep, BroadphaseMethod::Grid, BroadphaseMethod::Quadtree})
    {
        auto broadphase = hitbox::makeBroadphase(method);
        std::vector<Pair> pairs;
        broadphase->findPairs(items, pairs);
        const hitbox::BroadphaseLayout layout = broadphase->layout();
        const std::size_t parts =
            layout.boxesPerCell.size() + layout.nodes.size() + layout.sweepIntervals.size();
        EXPECT_GT(parts, 0u) << hitbox::toString(method);
    }
}

} // namespace
