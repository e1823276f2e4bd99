// Grading tests of lab 12 (the broad phase by hand). Each suite is named after the task it
// checks; README.md lists them. Every search must find exactly the pairs brute force finds
// (each once, touching boxes never), on seeded scenes where many boxes touch. Its exact
// tests are counted by the given ExactBoxTests (Given.cpp, always the course's copy), never
// by the search itself, and must be the ones its idea runs: sort and sweep tests the pairs
// open together on x, the grid the pairs sharing a cell, bound first the pairs whose
// bounding boxes overlap; each once, and every pair returned among them.
#include "BroadPhase.h"

#include "hitbox/geometry/Overlap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{

// Boxes on a coarse whole-number grid, so that many touch exactly on an edge or a corner.
std::vector<Box> crowdedBoxes(unsigned seed, int count, int spread)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> place(-spread, spread);
    std::uniform_int_distribution<int> size(0, 8);
    std::vector<Box> boxes;
    for (int index = 0; index < count; ++index)
    {
        const float left = static_cast<float>(place(random));
        const float top = static_cast<float>(place(random));
        // (A braced list is evaluated left to right: width first, then height.)
        boxes.push_back(
            {left, top, static_cast<float>(size(random)), static_cast<float>(size(random))});
    }
    return boxes;
}

// A diagonal chain: each box overlaps the next one only, so n - 1 pairs, and brute force
// still tests all n(n-1)/2.
std::vector<Box> chain(int count)
{
    std::vector<Box> boxes;
    for (int index = 0; index < count; ++index)
        boxes.push_back({index * 15.f, index * 15.f, 20.f, 20.f});
    return boxes;
}

// Every pair (first < second) for which `keep` holds: the tests' own brute force, written
// here so that nothing the search's file defines decides what is expected.
std::vector<Pair> pairsWhere(int count, const std::function<bool(int, int)>& keep)
{
    std::vector<Pair> pairs;
    for (int first = 0; first < count; ++first)
        for (int second = first + 1; second < count; ++second)
            if (keep(first, second))
                pairs.push_back({first, second});
    return pairs;
}

std::vector<Pair> overlappingBoxes(const std::vector<Box>& boxes)
{
    return pairsWhere(static_cast<int>(boxes.size()),
                      [&](int a, int b) { return hitbox::boxVsBox(boxes[a], boxes[b]); });
}

std::vector<Pair> sorted(std::vector<Pair> pairs)
{
    for (Pair& pair : pairs)
        if (pair.first > pair.second)
            std::swap(pair.first, pair.second);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

std::string text(const std::vector<Pair>& pairs)
{
    std::ostringstream out;
    for (std::size_t index = 0; index < pairs.size() && index < 12; ++index)
        out << "(" << pairs[index].first << ", " << pairs[index].second << ") ";
    if (pairs.size() > 12)
        out << "... " << pairs.size() << " in all";
    return out.str();
}

// The same pairs as brute force, each once.
testing::AssertionResult samePairs(const std::vector<Pair>& found,
                                   const std::vector<Pair>& expected)
{
    const std::vector<Pair> actual = sorted(found);
    if (actual == expected)
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << "found " << actual.size() << " pair(s): " << text(actual) << "\nbrute force finds "
           << expected.size()
           << " (touching boxes are not a pair, and each pair counts once): " << text(expected);
}

// What the exact tests of one search were: each pair once, every pair returned among them,
// none outside `allowed` (the idea's candidates; first < second) and none of `required` left
// out. A search that decides a pair another way, or tests more than its idea needs, fails.
testing::AssertionResult testedAsItsIdeaSays(const std::vector<Pair>& tested,
                                             const std::vector<Pair>& found,
                                             const std::vector<Pair>& allowed,
                                             const std::vector<Pair>& required, const char* idea)
{
    const std::vector<Pair> ran = sorted(tested);
    const auto repeat = std::adjacent_find(ran.begin(), ran.end());
    if (repeat != ran.end())
        return testing::AssertionFailure() << "the pair (" << repeat->first << ", "
                                           << repeat->second << ") was tested more than once";
    for (const Pair& pair : sorted(found))
        if (!std::binary_search(ran.begin(), ran.end(), pair))
            return testing::AssertionFailure()
                   << "the pair (" << pair.first << ", " << pair.second
                   << ") was returned without an exact test: every pair returned must come "
                      "from exact.overlap";
    for (const Pair& pair : ran)
        if (!std::binary_search(allowed.begin(), allowed.end(), pair))
            return testing::AssertionFailure()
                   << "the pair (" << pair.first << ", " << pair.second << ") was tested, but "
                   << idea << " never gets to it";
    for (const Pair& pair : required)
        if (!std::binary_search(ran.begin(), ran.end(), pair))
            return testing::AssertionFailure()
                   << "the pair (" << pair.first << ", " << pair.second << ") was not tested, but "
                   << idea << " must test it (" << ran.size() << " tests ran)";
    return testing::AssertionSuccess();
}

// Sort and sweep tests exactly the pairs open together on x: their x ranges overlap. Where
// they only touch, the open list may or may not still hold the older box; both are right.
testing::AssertionResult sweptAlongX(const std::vector<Box>& boxes, const ExactBoxTests& exact,
                                     const std::vector<Pair>& found)
{
    const int count = static_cast<int>(boxes.size());
    const auto along = [&](int a, int b) {
        return boxes[a].left < hitbox::rightOf(boxes[b]) &&
               boxes[b].left < hitbox::rightOf(boxes[a]);
    };
    const auto alongOrTouching = [&](int a, int b)
    {
        return boxes[a].left <= hitbox::rightOf(boxes[b]) &&
               boxes[b].left <= hitbox::rightOf(boxes[a]);
    };
    return testedAsItsIdeaSays(exact.tested(), found, pairsWhere(count, alongOrTouching),
                               pairsWhere(count, along), "sort and sweep along x");
}

// The cells a box covers along one axis, from `low` to `high` in cells `size` wide. The sheet
// counts a side exactly on a cell border into the next cell (wide); a grid that counts only
// the cells the box reaches inside (narrow: none for a box of no width) is right too. A grid
// tests every pair sharing a cell the narrow way, and no pair sharing none the wide way.
bool shareCells(float lowA, float highA, float lowB, float highB, float size, bool narrow)
{
    const auto first = [&](float low) { return std::floor(low / size); };
    const auto last = [&](float low, float high)
    {
        if (!narrow)
            return std::floor(high / size);
        return high > low ? std::ceil(high / size) - 1.f : first(low) - 1.f;
    };
    return first(lowA) <= last(lowB, highB) && first(lowB) <= last(lowA, highA) &&
           first(lowA) <= last(lowA, highA) && first(lowB) <= last(lowB, highB);
}

testing::AssertionResult testedCellByCell(const std::vector<Box>& boxes, float size,
                                          const ExactBoxTests& exact,
                                          const std::vector<Pair>& found)
{
    const auto sharing = [&](bool narrow)
    {
        return pairsWhere(static_cast<int>(boxes.size()),
                          [&](int a, int b)
                          {
                              const Box& p = boxes[a];
                              const Box& q = boxes[b];
                              return shareCells(p.left, hitbox::rightOf(p), q.left,
                                                hitbox::rightOf(q), size, narrow) &&
                                     shareCells(p.top, hitbox::bottomOf(p), q.top,
                                                hitbox::bottomOf(q), size, narrow);
                          });
    };
    return testedAsItsIdeaSays(exact.tested(), found, sharing(false), sharing(true),
                               "a grid of these cells");
}

} // namespace

TEST(Task1SortAndSweep, FindsTheSamePairsAsBruteForce)
{
    for (unsigned seed = 1; seed <= 20; ++seed)
    {
        const std::vector<Box> boxes = crowdedBoxes(seed, 60, 20);
        ExactBoxTests exact(boxes);
        const std::vector<Pair> found = sortAndSweepPairs(boxes, exact);
        EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes))) << "scene with seed " << seed;
        EXPECT_TRUE(sweptAlongX(boxes, exact, found)) << "scene with seed " << seed;
    }
}

TEST(Task1SortAndSweep, BoxesTouchingOnXAreNotAPair)
{
    // Each box starts exactly where the one before it ends (left, top, width, height).
    const std::vector<Box> chain = {
        {0.f, 0.f, 10.f, 10.f}, {10.f, 0.f, 10.f, 10.f}, {20.f, 0.f, 10.f, 10.f}};
    ExactBoxTests chainTests(chain);
    EXPECT_TRUE(samePairs(sortAndSweepPairs(chain, chainTests), {}));
    const std::vector<Box> overlapping = {{0.f, 0.f, 10.f, 10.f}, {9.5f, 0.f, 10.5f, 10.f}};
    ExactBoxTests overlappingTests(overlapping);
    EXPECT_TRUE(samePairs(sortAndSweepPairs(overlapping, overlappingTests), {{0, 1}}));
}

TEST(Task1SortAndSweep, TestsOnlyBoxesWhoseXRangesOverlap)
{
    const std::vector<Box> boxes = chain(200);
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = sortAndSweepPairs(boxes, exact);
    EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes)));
    // When a box arrives, only the box before it is still open on x.
    EXPECT_EQ(exact.tested().size(), 199u) << "of the " << 200 * 199 / 2 << " pairs";
    EXPECT_TRUE(sweptAlongX(boxes, exact, found));
}

TEST(Task2UniformGrid, FindsTheSamePairsAsBruteForceForEveryCellSize)
{
    for (unsigned seed = 1; seed <= 10; ++seed)
    {
        const std::vector<Box> boxes = crowdedBoxes(seed, 60, 20);
        const std::vector<Pair> expected = overlappingBoxes(boxes);
        // Cells smaller than the boxes (a pair shares many cells), equal, and larger; the
        // boxes reach negative coordinates, and many edges lie exactly on cell borders.
        for (const float cellSize : {2.f, 4.f, 8.f, 16.f, 64.f})
        {
            ExactBoxTests exact(boxes);
            const std::vector<Pair> found = gridPairs(boxes, cellSize, exact);
            EXPECT_TRUE(samePairs(found, expected))
                << "scene with seed " << seed << ", cells " << cellSize << " wide";
            EXPECT_TRUE(testedCellByCell(boxes, cellSize, exact, found))
                << "scene with seed " << seed << ", cells " << cellSize << " wide";
        }
    }
}

TEST(Task2UniformGrid, BoxesTouchingOnACellBorderAreNotAPair)
{
    // The edge rule where it meets the grid: two boxes that touch exactly on a cell border
    // share that border's cells, yet touching is not overlapping.
    const std::vector<Box> touching = {
        {0.f, 0.f, 8.f, 8.f}, {8.f, 0.f, 8.f, 8.f}, {0.f, 8.f, 8.f, 8.f}};
    ExactBoxTests touchingTests(touching);
    EXPECT_TRUE(samePairs(gridPairs(touching, 8.f, touchingTests), {}));
    const std::vector<Box> overlapping = {{0.f, 0.f, 8.5f, 8.f}, {8.f, 0.f, 8.f, 8.f}};
    ExactBoxTests overlappingTests(overlapping);
    EXPECT_TRUE(samePairs(gridPairs(overlapping, 8.f, overlappingTests), {{0, 1}}));
}

TEST(Task2UniformGrid, TestsFewerPairsThanBruteForce)
{
    const std::vector<Box> boxes = chain(200);
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = gridPairs(boxes, 64.f, exact);
    EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes)));
    EXPECT_LT(exact.tested().size(), 200u * 199u / 2u / 20u)
        << "boxes along a diagonal share cells only with their neighbours";
    EXPECT_TRUE(testedCellByCell(boxes, 64.f, exact, found));
}

TEST(Task2UniformGrid, EachPairSharingCellsIsTestedOnce)
{
    // Two overlapping boxes sharing four cells, and a third alone: one exact test, not four.
    const std::vector<Box> boxes = {
        {1.f, 1.f, 13.f, 13.f}, {2.f, 2.f, 13.f, 13.f}, {40.f, 40.f, 4.f, 4.f}};
    ExactBoxTests exact(boxes);
    EXPECT_TRUE(samePairs(gridPairs(boxes, 8.f, exact), {{0, 1}}));
    EXPECT_EQ(exact.tested().size(), 1u) << "a pair that shares several cells is tested once";
}

namespace
{

// Bound first tests exactly the pairs whose bounding squares overlap (strictly: squares that
// only touch cannot hold overlapping circles).
testing::AssertionResult testedWhereBoundsOverlap(const std::vector<Ball>& balls,
                                                  const ExactBallTests& exact,
                                                  const std::vector<Pair>& found)
{
    const auto bound = [](const Ball& ball) {
        return Box{ball.x - ball.radius, ball.y - ball.radius, 2.f * ball.radius,
                   2.f * ball.radius};
    };
    const std::vector<Pair> boundsOverlapping =
        pairsWhere(static_cast<int>(balls.size()), [&](int a, int b)
                   { return hitbox::boxVsBox(bound(balls[a]), bound(balls[b])); });
    return testedAsItsIdeaSays(exact.tested(), found, boundsOverlapping, boundsOverlapping,
                               "the bound-first search (the balls' own squares, strictly)");
}

std::vector<Pair> overlappingBalls(const std::vector<Ball>& balls)
{
    return pairsWhere(static_cast<int>(balls.size()),
                      [&](int a, int b)
                      {
                          const float dx = balls[a].x - balls[b].x;
                          const float dy = balls[a].y - balls[b].y;
                          const float reach = balls[a].radius + balls[b].radius;
                          return dx * dx + dy * dy < reach * reach;
                      });
}

} // namespace

TEST(Task3BoundFirst, FindsTheSameBallPairsAsTheExactTest)
{
    std::mt19937 random(7);
    std::uniform_int_distribution<int> place(0, 60);
    std::uniform_int_distribution<int> radius(0, 8);
    std::vector<Ball> balls;
    for (int index = 0; index < 80; ++index)
        balls.push_back({static_cast<float>(place(random)), static_cast<float>(place(random)),
                         static_cast<float>(radius(random))});
    // Touching on purpose: along x, along a 3-4-5 diagonal, and bounds touching at a corner.
    balls.push_back({200.f, 200.f, 5.f});
    balls.push_back({210.f, 200.f, 5.f});
    balls.push_back({300.f, 300.f, 2.f});
    balls.push_back({303.f, 304.f, 3.f});
    ExactBallTests exact(balls);
    const std::vector<Pair> found = ballPairsBoundFirst(balls, exact);
    EXPECT_TRUE(samePairs(found, overlappingBalls(balls)));
    EXPECT_TRUE(testedWhereBoundsOverlap(balls, exact, found));
}

TEST(Task3BoundFirst, RunsTheExactTestOnlyWhereTheBoundsOverlap)
{
    // Balls in a grid 30 apart, radius 10: no bounds overlap except the ones placed close.
    std::vector<Ball> balls;
    for (int row = 0; row < 10; ++row)
        for (int column = 0; column < 10; ++column)
            balls.push_back({column * 30.f, row * 30.f, 10.f});
    balls.push_back({1.f, 1.f, 1.f}); // its bound overlaps ball 0's; the circles overlap
    balls.push_back(
        {45.f, 15.f, 10.f}); // bounds overlap four balls' at their corners, circles none
    balls.push_back({90.f, 100.f, 5.f}); // bound and circle overlap ball (90, 90)'s
    ExactBallTests exact(balls);
    const std::vector<Pair> found = ballPairsBoundFirst(balls, exact);
    EXPECT_TRUE(samePairs(found, overlappingBalls(balls)));
    const std::size_t allPairs = balls.size() * (balls.size() - 1) / 2;
    EXPECT_TRUE(testedWhereBoundsOverlap(balls, exact, found))
        << "the exact circle test should run once for each pair whose bounding boxes overlap, "
           "and never otherwise; saved: "
        << allPairs - exact.tested().size() << " of " << allPairs;
    EXPECT_LT(exact.tested().size(), allPairs / 20);
}

TEST(Task3BoundFirst, TheBoundIsTheBallsOwnSquareNoBigger)
{
    // Two balls of radius 10 whose centres are 25 apart: their squares (x - radius to
    // x + radius) are 5 apart, so no exact test runs. Each ball on either side, along x and
    // along y: a square too wide or too tall on any side would reach the other one.
    const std::vector<std::vector<Ball>> pairs = {{{0.f, 0.f, 10.f}, {25.f, 0.f, 10.f}},
                                                  {{25.f, 0.f, 10.f}, {0.f, 0.f, 10.f}},
                                                  {{0.f, 0.f, 10.f}, {0.f, 25.f, 10.f}},
                                                  {{0.f, 25.f, 10.f}, {0.f, 0.f, 10.f}}};
    for (const std::vector<Ball>& balls : pairs)
    {
        ExactBallTests exact(balls);
        EXPECT_TRUE(ballPairsBoundFirst(balls, exact).empty());
        EXPECT_EQ(exact.tested().size(), 0u)
            << "balls at (" << balls[0].x << ", " << balls[0].y << ") and (" << balls[1].x << ", "
            << balls[1].y << "), radius 10: their bounding squares are 5 pixels apart";
    }
}
