// Grading tests of lab 12 (the broad phase by hand). Each suite is named after the task it
// checks; README.md lists them. Every search must find exactly the pairs brute force finds
// (each once, touching boxes never), on seeded scenes where many boxes touch, and must run
// fewer exact tests than brute force where the shapes are spread out.
#include "BroadPhase.h"

#include <gtest/gtest.h>

#include <algorithm>
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

} // namespace

TEST(Task1SortAndSweep, FindsTheSamePairsAsBruteForce)
{
    for (unsigned seed = 1; seed <= 20; ++seed)
    {
        const std::vector<Box> boxes = crowdedBoxes(seed, 60, 20);
        EXPECT_TRUE(samePairs(sortAndSweepPairs(boxes).pairs, bruteForcePairs(boxes).pairs))
            << "scene with seed " << seed;
    }
}

TEST(Task1SortAndSweep, BoxesTouchingOnXAreNotAPair)
{
    // Each box starts exactly where the one before it ends (left, top, width, height).
    const std::vector<Box> chain = {
        {0.f, 0.f, 10.f, 10.f}, {10.f, 0.f, 10.f, 10.f}, {20.f, 0.f, 10.f, 10.f}};
    EXPECT_TRUE(samePairs(sortAndSweepPairs(chain).pairs, {}));
    const std::vector<Box> overlapping = {{0.f, 0.f, 10.f, 10.f}, {9.5f, 0.f, 10.5f, 10.f}};
    EXPECT_TRUE(samePairs(sortAndSweepPairs(overlapping).pairs, {{0, 1}}));
}

TEST(Task1SortAndSweep, TestsOnlyBoxesWhoseXRangesOverlap)
{
    const std::vector<Box> boxes = chain(200);
    const PairSearch search = sortAndSweepPairs(boxes);
    EXPECT_TRUE(samePairs(search.pairs, bruteForcePairs(boxes).pairs));
    // When a box arrives, only the box before it is still open on x.
    EXPECT_EQ(search.exactTests, 199) << "of the " << bruteForcePairs(boxes).exactTests << " pairs";
}

TEST(Task2UniformGrid, FindsTheSamePairsAsBruteForceForEveryCellSize)
{
    for (unsigned seed = 1; seed <= 10; ++seed)
    {
        const std::vector<Box> boxes = crowdedBoxes(seed, 60, 20);
        const std::vector<Pair> expected = bruteForcePairs(boxes).pairs;
        // Cells smaller than the boxes (a pair shares many cells), equal, and larger; the
        // boxes reach negative coordinates, and many edges lie exactly on cell borders.
        for (const float cellSize : {2.f, 4.f, 8.f, 16.f, 64.f})
            EXPECT_TRUE(samePairs(gridPairs(boxes, cellSize).pairs, expected))
                << "scene with seed " << seed << ", cells " << cellSize << " wide";
    }
}

TEST(Task2UniformGrid, BoxesTouchingOnACellBorderAreNotAPair)
{
    // The edge rule where it meets the grid: two boxes that touch exactly on a cell border
    // share that border's cells, yet touching is not overlapping.
    const std::vector<Box> touching = {
        {0.f, 0.f, 8.f, 8.f}, {8.f, 0.f, 8.f, 8.f}, {0.f, 8.f, 8.f, 8.f}};
    EXPECT_TRUE(samePairs(gridPairs(touching, 8.f).pairs, {}));
    const std::vector<Box> overlapping = {{0.f, 0.f, 8.5f, 8.f}, {8.f, 0.f, 8.f, 8.f}};
    EXPECT_TRUE(samePairs(gridPairs(overlapping, 8.f).pairs, {{0, 1}}));
}

TEST(Task2UniformGrid, TestsFewerPairsThanBruteForce)
{
    const std::vector<Box> boxes = chain(200);
    const PairSearch search = gridPairs(boxes, 64.f);
    EXPECT_TRUE(samePairs(search.pairs, bruteForcePairs(boxes).pairs));
    EXPECT_LT(search.exactTests, bruteForcePairs(boxes).exactTests / 20)
        << "boxes along a diagonal share cells only with their neighbours";
    EXPECT_GE(search.exactTests, static_cast<long long>(search.pairs.size()))
        << "every pair found was tested exactly, and counted";
}

TEST(Task2UniformGrid, EachPairSharingCellsIsTestedOnce)
{
    // Two overlapping boxes sharing four cells, and a third alone: one exact test, not four.
    const std::vector<Box> boxes = {
        {1.f, 1.f, 13.f, 13.f}, {2.f, 2.f, 13.f, 13.f}, {40.f, 40.f, 4.f, 4.f}};
    const PairSearch search = gridPairs(boxes, 8.f);
    EXPECT_TRUE(samePairs(search.pairs, {{0, 1}}));
    EXPECT_EQ(search.exactTests, 1) << "a pair that shares several cells is tested once";
}

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
    std::vector<Pair> expected;
    for (int first = 0; first < static_cast<int>(balls.size()); ++first)
        for (int second = first + 1; second < static_cast<int>(balls.size()); ++second)
            if (overlaps(balls[first], balls[second]))
                expected.push_back({first, second});
    EXPECT_TRUE(samePairs(ballPairsBoundFirst(balls).pairs, expected));
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
    const PairSearch search = ballPairsBoundFirst(balls);
    long long boundsOverlapping = 0;
    for (std::size_t first = 0; first < balls.size(); ++first)
        for (std::size_t second = first + 1; second < balls.size(); ++second)
        {
            const Ball& a = balls[first];
            const Ball& b = balls[second];
            if (overlaps(Box{a.x - a.radius, a.y - a.radius, 2.f * a.radius, 2.f * a.radius},
                         Box{b.x - b.radius, b.y - b.radius, 2.f * b.radius, 2.f * b.radius}))
                ++boundsOverlapping;
        }
    const long long allPairs = static_cast<long long>(balls.size() * (balls.size() - 1) / 2);
    EXPECT_EQ(search.exactTests, boundsOverlapping)
        << "the exact circle test should run once for each pair whose bounding boxes overlap "
           "(strictly: bounds that only touch cannot hold overlapping circles), and never "
           "otherwise; saved: "
        << allPairs - search.exactTests << " of " << allPairs;
    EXPECT_LT(search.exactTests, allPairs / 20);
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
        const PairSearch search = ballPairsBoundFirst(balls);
        EXPECT_TRUE(search.pairs.empty());
        EXPECT_EQ(search.exactTests, 0)
            << "balls at (" << balls[0].x << ", " << balls[0].y << ") and (" << balls[1].x << ", "
            << balls[1].y << "), radius 10: their bounding squares are 5 pixels apart";
    }
}
