// BroadPhase.h - finding the pairs that touch among many shapes without testing them all.
//
// Plain values only (no SFML): boxes and balls in world pixels. Every search runs its exact
// tests through the given ExactBoxTests or ExactBallTests, which count and remember them, so
// you can see (and the tests can check) what each idea saves.
// The edge rule is the framework's: touching is not overlapping.
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <vector>

// Boxes are Hitbox's hitbox::Box (hitbox/geometry/Shapes.h): left, top, width, height; its
// right side is hitbox::rightOf(box), its bottom hitbox::bottomOf(box).
using hitbox::Box;

// A ball: centre and radius.
struct Ball
{
    float x = 0.f;
    float y = 0.f;
    float radius = 0.f;
};

// Two indices into the list searched, first < second.
struct Pair
{
    int first = 0;
    int second = 0;
};
bool operator==(const Pair& a, const Pair& b);
bool operator<(const Pair& a, const Pair& b);

// Given (Given.cpp, with everything else marked "Given"): the exact test of two of the boxes
// searched, by index. It keeps a reference to the boxes: use it while they live.
class ExactBoxTests
{
public:
    // What it keeps: every pair tested (what the grading tests read), or only how many (the
    // window: brute force on 20,000 boxes would keep 2 x 10^8 pairs a frame).
    enum class Keep
    {
        EveryPair,
        CountOnly
    };
    explicit ExactBoxTests(const std::vector<Box>& searched, Keep keep = Keep::EveryPair);
    ExactBoxTests(std::vector<Box>&&, Keep = Keep::EveryPair) = delete; // not a temporary list
    // Do boxes[first] and boxes[second] overlap? Strict: touching is not overlapping (Hitbox's
    // hitbox::boxVsBox). Counts one exact test and remembers the pair. An index outside the
    // list throws std::out_of_range.
    bool overlap(int first, int second);
    // How many exact tests ran so far.
    [[nodiscard]] long long count() const;
    // Every pair tested so far, in the order tested, as passed (empty with Keep::CountOnly).
    [[nodiscard]] const std::vector<Pair>& tested() const;

private:
    const std::vector<Box>* boxes; // not owned
    Keep keep;
    long long tests = 0;
    std::vector<Pair> testedPairs;
};

// Given: the same for balls: their exact circle test (strict), counted.
class ExactBallTests
{
public:
    explicit ExactBallTests(const std::vector<Ball>& searched);
    ExactBallTests(std::vector<Ball>&&) = delete; // it keeps a pointer: not a temporary list
    // Do balls[first] and balls[second] overlap? Strict: touching circles do not.
    bool overlap(int first, int second);
    [[nodiscard]] const std::vector<Pair>& tested() const;

private:
    const std::vector<Ball>* balls; // not owned
    std::vector<Pair> testedPairs;
};

// Given: Hitbox's box test for a cheap bound (task 3); not an exact test, so not counted.
[[nodiscard]] bool overlaps(const Box& a, const Box& b);
// Given: every pair once, n(n-1)/2 exact tests. The answer the others must match.
std::vector<Pair> bruteForcePairs(const std::vector<Box>& boxes, ExactBoxTests& exact);

// Task 1: sort the boxes by their left side, sweep from left to right keeping the boxes
// whose x range is still open, and test each new box against those only. Returns each
// overlapping pair once, in any order; every pair returned must have come from `exact`.
std::vector<Pair> sortAndSweepPairs(const std::vector<Box>& boxes, ExactBoxTests& exact);
// Task 2: a uniform grid of square cells `cellSize` wide, cell (0, 0) starting at (0, 0)
// (column floor(x / cellSize)): put each box in every cell it covers, then test only boxes
// that share a cell, each such pair once.
std::vector<Pair> gridPairs(const std::vector<Box>& boxes, float cellSize, ExactBoxTests& exact);
// Task 3: the balls that overlap, testing each pair's bounding boxes first (cheap,
// `overlaps`) and running the exact circle test only when those overlap.
std::vector<Pair> ballPairsBoundFirst(const std::vector<Ball>& balls, ExactBallTests& exact);
