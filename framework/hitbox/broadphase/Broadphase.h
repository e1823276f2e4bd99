// Broadphase.h - TEMPORARY STAND-IN written by the many-lab branch so the lab builds before
// the broadphase branch lands. It has the agreed interface; every method is brute force.
// The real file from branch `broadphase` replaces it on merge.
#pragma once

#include <SFML/Graphics/Rect.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace hitbox
{
class DebugRenderer;

struct BroadphaseItem
{
    sf::FloatRect box;
    std::uint32_t layer = 1;
    std::uint32_t mask = 0xFFFFFFFF;
};

struct Pair
{
    std::uint32_t first, second;
};

enum class BroadphaseMethod
{
    BruteForce,
    SortAndSweep,
    Grid,
    Quadtree
};

struct BroadphaseStats
{
    std::size_t pairsTested = 0;
    std::size_t pairsFound = 0;
};

class Broadphase
{
public:
    virtual ~Broadphase() = default;
    virtual void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) = 0;
    virtual const char* name() const = 0;
    virtual BroadphaseStats stats() const = 0;
    virtual void drawDebug(DebugRenderer& debug) const = 0;
};

std::unique_ptr<Broadphase> makeBroadphase(BroadphaseMethod method);
const char* toString(BroadphaseMethod method);

} // namespace hitbox
