// QuadtreeBroadphase.h - split the world into four, again and again where it is crowded
// (seed 003: "a quadtree divides the map into regions so an object is only checked
// against objects in its own region").
//
// Rebuilt every frame. Each box lives in the smallest node that holds it whole, so a box
// lying across a split line stays in the bigger node above. Two boxes can only share area if
// one's node is the other's node or one of its ancestors, so each box is tested against the
// boxes of its own node and of the nodes above it.
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
    const char* name() const override { return "Quadtree"; }
    BroadphaseStats stats() const override { return lastStats; }
    // Outlines every node of the last frame's tree.
    void drawDebug(DebugRenderer& debug) const override;

private:
    struct Node
    {
        sf::FloatRect region;
        std::uint32_t itemsBegin = 0; // this node's own boxes: order[itemsBegin .. itemsEnd)
        std::uint32_t itemsEnd = 0;
        std::int32_t children[4] = {-1, -1, -1, -1};
    };

    std::int32_t build(const sf::FloatRect& region, std::uint32_t begin, std::uint32_t end,
                       int depth);
    void testNode(std::int32_t nodeIndex, std::vector<Pair>& pairs);

    std::size_t nodeCapacity;
    int maxDepth;
    BoxArrays boxes;
    std::vector<std::uint32_t> order;     // item indices, grouped by node
    std::vector<Node> nodes;              // nodes[0] is the root
    std::vector<std::uint32_t> ancestors; // boxes of the nodes above, while testing
    std::size_t tested = 0;
    BroadphaseStats lastStats;
};

} // namespace hitbox
