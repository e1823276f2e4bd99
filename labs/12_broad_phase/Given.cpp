// Given.cpp - the code given to you in lab 12: the exact tests, which count themselves, and
// brute force. Yours is BroadPhase.cpp. The grading tests count and compare with this file,
// so the grader always uses the course's copy of it: a change here changes nothing there.
#include "BroadPhase.h"

#include "hitbox/geometry/Overlap.h"

#include <cstddef>

bool operator==(const Pair& a, const Pair& b)
{
    return a.first == b.first && a.second == b.second;
}

bool operator<(const Pair& a, const Pair& b)
{
    return a.first != b.first ? a.first < b.first : a.second < b.second;
}

ExactBoxTests::ExactBoxTests(const std::vector<Box>& searched, Keep kept)
    : boxes(&searched), keep(kept)
{
}

bool ExactBoxTests::overlap(int first, int second)
{
    ++tests;
    if (keep == Keep::EveryPair)
        testedPairs.push_back({first, second});
    return hitbox::boxVsBox(boxes->at(static_cast<std::size_t>(first)),
                            boxes->at(static_cast<std::size_t>(second)));
}

long long ExactBoxTests::count() const
{
    return tests;
}

const std::vector<Pair>& ExactBoxTests::tested() const
{
    return testedPairs;
}

ExactBallTests::ExactBallTests(const std::vector<Ball>& searched) : balls(&searched) {}

bool ExactBallTests::overlap(int first, int second)
{
    testedPairs.push_back({first, second});
    const Ball& a = balls->at(static_cast<std::size_t>(first));
    const Ball& b = balls->at(static_cast<std::size_t>(second));
    const float dx = a.x - b.x;
    const float dy = a.y - b.y;
    const float reach = a.radius + b.radius;
    return dx * dx + dy * dy < reach * reach;
}

const std::vector<Pair>& ExactBallTests::tested() const
{
    return testedPairs;
}

bool overlaps(const Box& a, const Box& b)
{
    return hitbox::boxVsBox(a, b);
}

std::vector<Pair> bruteForcePairs(const std::vector<Box>& boxes, ExactBoxTests& exact)
{
    std::vector<Pair> pairs;
    const int count = static_cast<int>(boxes.size());
    for (int first = 0; first < count; ++first)
        for (int second = first + 1; second < count; ++second)
            if (exact.overlap(first, second))
                pairs.push_back({first, second});
    return pairs;
}
