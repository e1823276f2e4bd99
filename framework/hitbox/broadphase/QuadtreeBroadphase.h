// QuadtreeBroadphase.h - split the world into four, again and again where it is crowded
// (Ericson, Real-Time Collision Detection, 7.3.1): a box is only checked against the
// boxes in its own region.
//
// Rebuilt every frame. A box goes down to the quarter that holds its centre, as long as it
// fits inside that quarter grown by half its size on every side (a "loose" quadtree). Without
// the growth, every box lying across a split line would have to stay in the big node above,
// and with many boxes those nodes fill up. Then, for each box, walk down only into the nodes
// whose (grown) area touches the box, and test the boxes stored there.
#pragma once

#include "hitbox/broadphase/BoxArrays.h"
#include "hitbox/broadphase/Broadphase.h"

namespace hitbox
{

class QuadtreeBroadphase : public Broadphase
{
public:
    // A node splits when it holds more than `nodeCapacity` boxes, down to `maxDepth` levels.
    explicit QuadtreeBroadphase(std::size_t nodeCapacity = 8, int maxDepth = 10);

    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override;
    [[nodiscard]] const char* name() const override { return "Quadtree"; }
    [[nodiscard]] BroadphaseStats stats() const override { return lastStats; }
    // Every node's region.
    [[nodiscard]] BroadphaseLayout layout() const override;

private:
    struct Bounds
    {
        float minX, minY, maxX, maxY;
    };
    struct Node
    {
        Bounds region;                // the node's own quarter of its parent
        Bounds loose;                 // the region grown by half its size: boxes stored here
        std::uint32_t itemsBegin = 0; // this node's own boxes: order[itemsBegin .. itemsEnd)
        std::uint32_t itemsEnd = 0;
        std::int32_t children[4] = {-1, -1, -1, -1};
    };

    std::int32_t build(const Bounds& region, const Bounds& loose, std::uint32_t begin,
                       std::uint32_t end, int depth);
    void findPairsOf(std::uint32_t item, std::vector<Pair>& pairs);

    std::size_t nodeCapacity;
    int maxDepth;
    BoxArrays boxes;
    std::vector<std::uint32_t> order; // item indices, grouped by node
    std::vector<Node> nodes;          // nodes[0] is the root
    std::vector<std::int32_t> stack;  // nodes still to visit, while searching
    std::size_t tested = 0;
    BroadphaseStats lastStats;
};

} // namespace hitbox
