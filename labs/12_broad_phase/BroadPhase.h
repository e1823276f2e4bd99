// BroadPhase.h - finding the pairs that touch among many shapes without testing them all.
//
// Plain values only (no SFML): boxes and balls in world pixels. Every search returns the
// pairs it found and how many exact tests it ran, so you can see what each idea saves.
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

struct PairSearch
{
    std::vector<Pair> pairs;  // each overlapping pair once, in any order
    long long exactTests = 0; // how many times the exact test ran
};

// Given: the exact tests. Strict: touching does not overlap. For two boxes it is Hitbox's
// own hitbox::boxVsBox (hitbox/geometry/Overlap.h).
bool overlaps(const Box& a, const Box& b);
bool overlaps(const Ball& a, const Ball& b);
// Given: every pair once, n(n-1)/2 exact tests. The answer the others must match.
PairSearch bruteForcePairs(const std::vector<Box>& boxes);

// Task 1: sort the boxes by their left side, sweep from left to right keeping the boxes
// whose x range is still open, and test each new box against those only.
PairSearch sortAndSweepPairs(const std::vector<Box>& boxes);
// Task 2: a uniform grid of square cells `cellSize` wide: put each box in every cell it
// covers, then test only boxes that share a cell; report each pair once.
PairSearch gridPairs(const std::vector<Box>& boxes, float cellSize);
// Task 3: the balls that overlap, testing each pair's bounding boxes first (cheap) and
// running the exact circle test only when those overlap.
PairSearch ballPairsBoundFirst(const std::vector<Ball>& balls);
