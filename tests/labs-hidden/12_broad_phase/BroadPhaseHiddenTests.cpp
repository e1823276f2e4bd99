// Hidden variants of lab 12's grading tests: the same behaviour as BroadPhaseGradingTests.cpp
// with other scenes, seeds, cell sizes and radii. The instructor's build and the class grader
// run them; the student handout leaves tests/labs-hidden/ out, so no one can tune an answer
// to them. As in the visible tests, the given ExactBoxTests / ExactBallTests (Given.cpp) count
// the exact tests, and each search must test the pairs its idea reaches, each once.
#include "labs/12_broad_phase/BroadPhaseChecks.h"

#include "BroadPhase.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

namespace
{

using namespace broadphasechecks;

// Boxes on a half-pixel grid, reaching well below zero: many edges meet exactly, at places
// (and in an order) the visible scenes never use.
std::vector<Box> halfPixelBoxes(unsigned seed)
{
    return crowdedBoxes(seed, 45, -24, 24, 13, 0.5f);
}

// A chain up and to the left, listed from its right end: each box overlaps only the next in
// the list, and the list is in the opposite order to the boxes' left sides.
std::vector<Box> backwardChain(int count)
{
    return diagonalChain(count, -12.f, 16.f);
}

} // namespace

TEST(Task1SortAndSweep, HiddenFindsTheSamePairsOnHalfPixelScenes)
{
    for (unsigned seed = 301; seed <= 315; ++seed)
        expectSweepFindsThePairs(halfPixelBoxes(seed), "scene " + std::to_string(seed));
}

TEST(Task1SortAndSweep, HiddenABackwardChainNeedsOneTestPerLink)
{
    // Listed right to left: a sweep that skips the sort never closes a box in time and tests
    // every pair; a count tuned to the visible 200-box chain is wrong for 150.
    const std::vector<Box> boxes = backwardChain(150);
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = sortAndSweepPairs(boxes, exact);
    EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes)));
    EXPECT_EQ(found.size(), 149u);
    EXPECT_EQ(exact.tested().size(), 149u) << "of the " << 150 * 149 / 2 << " pairs";
    EXPECT_TRUE(sweptAlongX(boxes, exact, found));
}

TEST(Task1SortAndSweep, HiddenAStackTouchingOnYIsTestedButNoPair)
{
    // The same x range, each box starting exactly where the one above ends: all open together
    // on x, so they are tested, but touching is not overlapping. The last box dips a quarter
    // pixel into the one above it: that is a pair.
    const std::vector<Box> stack = {
        {5.f, 8.f, 7.f, 4.f}, {5.f, 0.f, 7.f, 4.f}, {5.f, 4.f, 7.f, 4.f}, {5.f, 11.75f, 7.f, 4.f}};
    ExactBoxTests exact(stack);
    const std::vector<Pair> found = sortAndSweepPairs(stack, exact);
    EXPECT_TRUE(samePairs(found, {{0, 3}}));
    EXPECT_TRUE(sweptAlongX(stack, exact, found));
}

TEST(Task2UniformGrid, HiddenFindsTheSamePairsForOddCellSizes)
{
    // Cells that do not divide the boxes' half-pixel grid evenly, and some that do.
    for (unsigned seed = 501; seed <= 508; ++seed)
        expectGridPairsForEachCellSize(halfPixelBoxes(seed), {1.5f, 3.f, 5.f, 7.5f, 40.f},
                                       "scene " + std::to_string(seed));
}

TEST(Task2UniformGrid, HiddenBoxesTouchingOnANegativeCellBorderAreNotAPair)
{
    // Left of and above zero, on the border x = -6 and y = -6 of 6-pixel cells: they share the
    // border's cells but only touch. Half a pixel more and it is a pair.
    const std::vector<Box> touching = {
        {-12.f, -12.f, 6.f, 6.f}, {-6.f, -12.f, 6.f, 6.f}, {-12.f, -6.f, 6.f, 6.f}};
    ExactBoxTests touchingTests(touching);
    const std::vector<Pair> none = gridPairs(touching, 6.f, touchingTests);
    EXPECT_TRUE(samePairs(none, {}));
    EXPECT_TRUE(testedCellByCell(touching, 6.f, touchingTests, none));
    const std::vector<Box> overlapping = {{-12.f, -12.f, 6.f, 6.f}, {-12.f, -6.5f, 6.f, 6.f}};
    ExactBoxTests overlappingTests(overlapping);
    const std::vector<Pair> one = gridPairs(overlapping, 6.f, overlappingTests);
    EXPECT_TRUE(samePairs(one, {{0, 1}}));
    EXPECT_TRUE(testedCellByCell(overlapping, 6.f, overlappingTests, one));
}

TEST(Task2UniformGrid, HiddenTwoPairsSharingManyCellsAreTestedOnceEach)
{
    // Boxes 1 and 3 share nine 5-pixel cells, boxes 0 and 4 four; box 2 is alone. Two exact
    // tests, whatever the order of the list.
    const std::vector<Box> boxes = {{100.f, 100.f, 6.f, 6.f},
                                    {0.5f, 0.5f, 14.f, 14.f},
                                    {-40.f, -40.f, 3.f, 3.f},
                                    {3.f, 3.f, 14.f, 14.f},
                                    {104.f, 101.f, 6.f, 6.f}};
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = gridPairs(boxes, 5.f, exact);
    EXPECT_TRUE(samePairs(found, {{0, 4}, {1, 3}}));
    EXPECT_EQ(exact.tested().size(), 2u) << "a pair sharing several cells is tested once";
}

TEST(Task2UniformGrid, HiddenABackwardChainTestsOnlyNeighbours)
{
    const std::vector<Box> boxes = backwardChain(150);
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = gridPairs(boxes, 32.f, exact);
    EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes)));
    EXPECT_LT(exact.tested().size(), 150u * 149u / 2u / 20u);
    EXPECT_TRUE(testedCellByCell(boxes, 32.f, exact, found));
}

TEST(Task3BoundFirst, HiddenFindsTheSameBallPairsAmongHalfPixelBalls)
{
    std::vector<Ball> balls = crowdedBalls(4242, 90, -80, 80, 14, 0.5f);
    // Touching on a 5-12-13 diagonal (squares overlap, circles only touch), and squares that
    // only touch at a corner (never tested).
    balls.push_back({-150.f, -150.f, 6.f});
    balls.push_back({-145.f, -138.f, 7.f});
    balls.push_back({400.f, 400.f, 3.f});
    balls.push_back({406.f, 394.f, 3.f});
    expectBoundFirstFindsThePairs(balls);
}

TEST(Task3BoundFirst, HiddenEachBallsSquareUsesItsOwnRadius)
{
    // A small ball (radius 4) and a big one (radius 12), on every side of each other. Squares
    // 1 px apart: no exact test. Squares overlapping with circles apart: one exact test and
    // no pair. A square built from the other ball's radius, or too small, gets one of them wrong.
    struct Case
    {
        Ball small;
        Ball big;
        std::size_t tests;
    };
    const Case cases[] = {
        {{0.f, 0.f, 4.f}, {17.f, 0.f, 12.f}, 0u},  {{0.f, 0.f, 4.f}, {-17.f, 0.f, 12.f}, 0u},
        {{0.f, 0.f, 4.f}, {0.f, 17.f, 12.f}, 0u},  {{0.f, 0.f, 4.f}, {0.f, -17.f, 12.f}, 0u},
        {{0.f, 0.f, 4.f}, {14.f, 10.f, 12.f}, 1u}, {{0.f, 0.f, 4.f}, {-14.f, -10.f, 12.f}, 1u},
    };
    for (const Case& test : cases)
        for (const bool smallFirst : {true, false})
        {
            const std::vector<Ball> balls = smallFirst ? std::vector<Ball>{test.small, test.big}
                                                       : std::vector<Ball>{test.big, test.small};
            ExactBallTests exact(balls);
            EXPECT_TRUE(ballPairsBoundFirst(balls, exact).empty());
            EXPECT_EQ(exact.tested().size(), test.tests)
                << "big ball at (" << test.big.x << ", " << test.big.y
                << "), radius 12, small ball at (0, 0), radius 4"
                << (smallFirst ? ", small one listed first" : ", big one listed first");
        }
}
