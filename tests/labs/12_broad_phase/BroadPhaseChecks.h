// BroadPhaseChecks.h - lab 12's scenes, the tests' own brute force and the checks that each
// search finds the right pairs through exactly the exact tests its idea runs. Both the grading
// tests (BroadPhaseGradingTests.cpp) and their hidden variants
// (tests/labs-hidden/12_broad_phase/) use it.
#pragma once

#include "BroadPhase.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace broadphasechecks
{

// Seeded shapes with every coordinate on a coarse grid, so that many touch exactly.
template <typename Shape, typename Make>
inline std::vector<Shape> onAGrid(unsigned seed, int count, int low, int high, int largest,
                                  float unit, const Make& make)
{
    // `make` builds one shape from two draws, in grid steps of `unit` pixels: `place()`, a
    // coordinate from `low` to `high` steps, and `size()`, a length from 0 to `largest` steps.
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> placeSteps(low, high);
    std::uniform_int_distribution<int> sizeSteps(0, largest);
    const auto place = [&] { return unit * static_cast<float>(placeSteps(random)); };
    const auto size = [&] { return unit * static_cast<float>(sizeSteps(random)); };
    std::vector<Shape> shapes;
    for (int index = 0; index < count; ++index)
        shapes.push_back(make(place, size));
    return shapes;
}

// Seeded boxes on a coarse grid, so that many touch exactly on an edge or a corner.
inline std::vector<Box> crowdedBoxes(unsigned seed, int count, int low, int high, int largest,
                                     float unit)
{
    // (A braced list is evaluated left to right: left, top, width, height.)
    return onAGrid<Box>(seed, count, low, high, largest, unit,
                        [](const auto& place, const auto& size) {
                            return Box{place(), place(), size(), size()};
                        });
}

// Seeded balls on a coarse grid, so that many circles and bounding squares touch exactly.
inline std::vector<Ball> crowdedBalls(unsigned seed, int count, int low, int high, int largest,
                                      float unit)
{
    // (A braced list is evaluated left to right: x, y, radius.)
    return onAGrid<Ball>(seed, count, low, high, largest, unit,
                         [](const auto& place, const auto& size) {
                             return Ball{place(), place(), size()};
                         });
}

// A diagonal chain where brute force tests all n(n-1)/2 pairs but only n - 1 overlap.
inline std::vector<Box> diagonalChain(int count, float step, float size)
{
    // Each box `step` on from the one before along both axes (a negative step runs up and to
    // the left, so the list is in the opposite order to the boxes' left sides).
    std::vector<Box> boxes;
    for (int index = 0; index < count; ++index)
        boxes.push_back({index * step, index * step, size, size});
    return boxes;
}

// The tests' own brute force, so that nothing the search's file defines decides what is expected.
inline std::vector<Pair> pairsWhere(int count, const std::function<bool(int, int)>& keep)
{
    // Every pair (first < second) for which `keep` holds.
    std::vector<Pair> pairs;
    for (int first = 0; first < count; ++first)
        for (int second = first + 1; second < count; ++second)
            if (keep(first, second))
                pairs.push_back({first, second});
    return pairs;
}

// The box pairs a correct search must find: overlapping strictly, touching never.
inline std::vector<Pair> overlappingBoxes(const std::vector<Box>& boxes)
{
    return pairsWhere(static_cast<int>(boxes.size()),
                      [&](int a, int b) { return hitbox::boxVsBox(boxes[a], boxes[b]); });
}

// The ball pairs a correct search must find: circles overlapping strictly, touching never.
inline std::vector<Pair> overlappingBalls(const std::vector<Ball>& balls)
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

// Pairs in one order (first < second, sorted), since a search may return them in any order.
inline std::vector<Pair> sorted(std::vector<Pair> pairs)
{
    for (Pair& pair : pairs)
        if (pair.first > pair.second)
            std::swap(pair.first, pair.second);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// A list of pairs short enough to read in a failure message.
inline std::string text(const std::vector<Pair>& pairs)
{
    std::ostringstream out;
    for (std::size_t index = 0; index < pairs.size() && index < 12; ++index)
        out << "(" << pairs[index].first << ", " << pairs[index].second << ") ";
    if (pairs.size() > 12)
        out << "... " << pairs.size() << " in all";
    return out.str();
}

// A search is right when it finds the same pairs as brute force, each once.
inline testing::AssertionResult samePairs(const std::vector<Pair>& found,
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

// A search that decides a pair another way, or tests more than its idea needs, saves nothing.
inline testing::AssertionResult testedAsItsIdeaSays(const std::vector<Pair>& tested,
                                                    const std::vector<Pair>& found,
                                                    const std::vector<Pair>& allowed,
                                                    const std::vector<Pair>& required,
                                                    const char* idea)
{
    // What the exact tests of one search were: each pair once, every pair returned among them,
    // none outside `allowed` (the idea's candidates; first < second) and none of `required`
    // left out.
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

// Sort and sweep saves its tests by testing only the pairs open together on x.
inline testing::AssertionResult sweptAlongX(const std::vector<Box>& boxes,
                                            const ExactBoxTests& exact,
                                            const std::vector<Pair>& found)
{
    // The pairs whose x ranges overlap must be tested. Where they only touch, the open list may
    // or may not still hold the older box; both are right.
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

// Sort and sweep must find brute force's pairs, testing only the pairs open together on x.
inline void expectSweepFindsThePairs(const std::vector<Box>& boxes, const std::string& scene)
{
    ExactBoxTests exact(boxes);
    const std::vector<Pair> found = sortAndSweepPairs(boxes, exact);
    EXPECT_TRUE(samePairs(found, overlappingBoxes(boxes))) << scene;
    EXPECT_TRUE(sweptAlongX(boxes, exact, found)) << scene;
}

// Whether two boxes' spans along one axis land in a common grid cell, the way a grid decides.
inline bool shareCells(float lowA, float highA, float lowB, float highB, float size, bool narrow)
{
    // The cells a span covers, from `low` to `high` in cells `size` wide. The sheet counts a
    // side exactly on a cell border into the next cell (wide); a grid that counts only the
    // cells the box reaches inside (narrow: none for a box of no width) is right too.
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

// A grid saves its tests by testing only the pairs that share a cell, each once.
inline testing::AssertionResult testedCellByCell(const std::vector<Box>& boxes, float size,
                                                 const ExactBoxTests& exact,
                                                 const std::vector<Pair>& found)
{
    // Every pair sharing a cell the narrow way must be tested, and no pair sharing none the
    // wide way may be.
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
                               "a grid of these cells (cell (0, 0) at (0, 0))");
}

// A grid must find brute force's pairs at every cell size, through the tests its idea runs.
inline void expectGridPairsForEachCellSize(const std::vector<Box>& boxes,
                                           std::initializer_list<float> cellSizes,
                                           const std::string& scene)
{
    const std::vector<Pair> expected = overlappingBoxes(boxes);
    for (const float cellSize : cellSizes)
    {
        ExactBoxTests exact(boxes);
        const std::vector<Pair> found = gridPairs(boxes, cellSize, exact);
        EXPECT_TRUE(samePairs(found, expected)) << scene << ", cells " << cellSize << " wide";
        EXPECT_TRUE(testedCellByCell(boxes, cellSize, exact, found))
            << scene << ", cells " << cellSize << " wide";
    }
}

// A ball's own bounding square: anything bigger lets bound first run exact tests it could skip.
inline Box squareAround(const Ball& ball)
{
    return {ball.x - ball.radius, ball.y - ball.radius, 2.f * ball.radius, 2.f * ball.radius};
}

// Bound first saves its tests by running the exact test only where the balls' squares overlap.
inline testing::AssertionResult testedWhereBoundsOverlap(const std::vector<Ball>& balls,
                                                         const ExactBallTests& exact,
                                                         const std::vector<Pair>& found)
{
    // Strictly: squares that only touch cannot hold overlapping circles.
    const std::vector<Pair> boundsOverlapping =
        pairsWhere(static_cast<int>(balls.size()), [&](int a, int b)
                   { return hitbox::boxVsBox(squareAround(balls[a]), squareAround(balls[b])); });
    return testedAsItsIdeaSays(exact.tested(), found, boundsOverlapping, boundsOverlapping,
                               "the bound-first search (the balls' own squares, strictly)");
}

// Bound first must find the pairs the exact test finds, running it only where squares overlap.
inline void expectBoundFirstFindsThePairs(const std::vector<Ball>& balls)
{
    ExactBallTests exact(balls);
    const std::vector<Pair> found = ballPairsBoundFirst(balls, exact);
    EXPECT_TRUE(samePairs(found, overlappingBalls(balls)));
    EXPECT_TRUE(testedWhereBoundsOverlap(balls, exact, found));
}

} // namespace broadphasechecks
