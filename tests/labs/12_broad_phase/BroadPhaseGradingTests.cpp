// Grading tests of lab 12 (the broad phase by hand). Each suite is named after the task it
// checks; README.md lists them. Every search must find exactly the pairs brute force finds
// (each once, touching boxes never), on seeded scenes where many boxes touch. Its exact
// tests are counted by the given ExactBoxTests (Given.cpp, always the course's copy), never
// by the search itself, and must be the ones its idea runs: sort and sweep tests the pairs
// open together on x, the grid the pairs sharing a cell, bound first the pairs whose
// bounding boxes overlap; each once, and every pair returned among them.
#include "labs/12_broad_phase/BroadPhaseChecks.h"

#include "BroadPhase.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

namespace
{
using namespace broadphasechecks;
} // namespace

TEST(Task1SortAndSweep, FindsTheSamePairsAsBruteForce)
{
    for (unsigned seed = 1; seed <= 20; ++seed)
        expectSweepFindsThePairs(crowdedBoxes(seed, 60, -20, 20, 8, 1.f),
                                 "scene with seed " + std::to_string(seed));
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
    const std::vector<Box> boxes = diagonalChain(200, 15.f, 20.f);
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = sortAndSweepPairs(boxes, exact);
    EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes)));
    // When a box arrives, only the box before it is still open on x.
    EXPECT_EQ(exact.tested().size(), 199u) << "of the " << 200 * 199 / 2 << " pairs";
    EXPECT_TRUE(sweptAlongX(boxes, exact, found));
}

TEST(Task2UniformGrid, FindsTheSamePairsAsBruteForceForEveryCellSize)
{
    // Cells smaller than the boxes (a pair shares many cells), equal, and larger; the boxes
    // reach negative coordinates, and many edges lie exactly on cell borders.
    for (unsigned seed = 1; seed <= 10; ++seed)
        expectGridPairsForEachCellSize(crowdedBoxes(seed, 60, -20, 20, 8, 1.f),
                                       {2.f, 4.f, 8.f, 16.f, 64.f},
                                       "scene with seed " + std::to_string(seed));
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
    const std::vector<Box> boxes = diagonalChain(200, 15.f, 20.f);
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

TEST(Task3BoundFirst, FindsTheSameBallPairsAsTheExactTest)
{
    std::vector<Ball> balls = crowdedBalls(7, 80, 0, 60, 8, 1.f);
    // Touching on purpose: along x, along a 3-4-5 diagonal, and bounds touching at a corner.
    balls.push_back({200.f, 200.f, 5.f});
    balls.push_back({210.f, 200.f, 5.f});
    balls.push_back({300.f, 300.f, 2.f});
    balls.push_back({303.f, 304.f, 3.f});
    expectBoundFirstFindsThePairs(balls);
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
