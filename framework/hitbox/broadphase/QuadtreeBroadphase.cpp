#include "hitbox/broadphase/QuadtreeBroadphase.h"

#include <algorithm>
#include <numeric>

namespace hitbox
{

QuadtreeBroadphase::QuadtreeBroadphase(std::size_t capacity, int depth)
    : nodeCapacity(capacity), maxDepth(depth)
{
}

std::int32_t QuadtreeBroadphase::build(const sf::FloatRect& region, std::uint32_t begin,
                                       std::uint32_t end, int depth)
{
    const std::int32_t index = static_cast<std::int32_t>(nodes.size());
    nodes.push_back(Node{region, begin, end, {-1, -1, -1, -1}});
    if (end - begin <= nodeCapacity || depth >= maxDepth)
        return index; // a leaf: all its boxes stay here

    const float midX = region.left + region.width / 2.f;
    const float midY = region.top + region.height / 2.f;
    const float right = rightOf(region);
    const float bottom = bottomOf(region);
    const sf::FloatRect quarters[4] = {
        {region.left, region.top, midX - region.left, midY - region.top},
        {midX, region.top, right - midX, midY - region.top},
        {region.left, midY, midX - region.left, bottom - midY},
        {midX, midY, right - midX, bottom - midY}};
    // [slide:quadtree-insert]
    // A box goes down into a quarter only if it fits there whole. The quarters share their
    // split lines, but touching is not colliding, so boxes in different quarters can never
    // share area. A box lying across a split line stays in this node.
    auto fitsIn = [this](std::uint32_t item, float left, float top, float r, float b)
    {
        return boxes.minX[item] >= left && boxes.maxX[item] <= r && boxes.minY[item] >= top &&
               boxes.maxY[item] <= b;
    };
    auto fitsQuarter = [&](std::uint32_t item, int q)
    {
        return fitsIn(item, quarters[q].left, quarters[q].top, q % 2 == 0 ? midX : right,
                      q < 2 ? midY : bottom);
    };
    std::uint32_t* cursor = order.data() + begin;
    std::uint32_t* last = order.data() + end;
    // Boxes that fit no quarter move to the front: they are this node's own boxes.
    cursor = std::partition(cursor, last,
                            [&](std::uint32_t item)
                            {
                                return !fitsQuarter(item, 0) && !fitsQuarter(item, 1) &&
                                       !fitsQuarter(item, 2) && !fitsQuarter(item, 3);
                            });
    // [/slide]
    nodes[index].itemsEnd = static_cast<std::uint32_t>(cursor - order.data());
    for (int q = 0; q < 4; ++q)
    {
        // The boxes for quarter q move next (a box on a split line goes to the first fit).
        std::uint32_t* childEnd =
            std::partition(cursor, last, [&](std::uint32_t item) { return fitsQuarter(item, q); });
        if (childEnd != cursor)
        {
            const std::int32_t child =
                build(quarters[q], static_cast<std::uint32_t>(cursor - order.data()),
                      static_cast<std::uint32_t>(childEnd - order.data()), depth + 1);
            nodes[index].children[q] = child; // not a reference: build() grew `nodes`
        }
        cursor = childEnd;
    }
    return index;
}

void QuadtreeBroadphase::testNode(std::int32_t nodeIndex, std::vector<Pair>& pairs)
{
    const Node node = nodes[static_cast<std::size_t>(nodeIndex)];
    // Each own box against the later own boxes, and against every box of the nodes above.
    for (std::uint32_t p = node.itemsBegin; p < node.itemsEnd; ++p)
    {
        const std::uint32_t a = order[p];
        for (std::uint32_t q = p + 1; q < node.itemsEnd; ++q)
        {
            const std::uint32_t b = order[q];
            if (!boxes.allowed(a, b))
                continue;
            ++tested;
            if (boxes.overlap(a, b))
                pairs.push_back({std::min(a, b), std::max(a, b)});
        }
        for (const std::uint32_t b : ancestors)
        {
            if (!boxes.allowed(a, b))
                continue;
            ++tested;
            if (boxes.overlap(a, b))
                pairs.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    const std::size_t ancestorsBefore = ancestors.size();
    ancestors.insert(ancestors.end(), order.begin() + node.itemsBegin,
                     order.begin() + node.itemsEnd);
    for (const std::int32_t child : node.children)
    {
        if (child >= 0)
            testNode(child, pairs);
    }
    ancestors.resize(ancestorsBefore);
}

void QuadtreeBroadphase::findPairs(const std::vector<BroadphaseItem>& items,
                                   std::vector<Pair>& pairs)
{
    pairs.clear();
    nodes.clear();
    ancestors.clear();
    tested = 0;
    boxes.load(items);

    // The root covers every usable box; NaN boxes are left out of the tree.
    order.clear();
    sf::FloatRect root;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
    {
        if (!boxes.isUsable(i))
            continue;
        if (order.empty())
            root = {boxes.minX[i], boxes.minY[i], 0.f, 0.f};
        const float left = std::min(root.left, boxes.minX[i]);
        const float top = std::min(root.top, boxes.minY[i]);
        const float right = std::max(rightOf(root), boxes.maxX[i]);
        const float bottom = std::max(bottomOf(root), boxes.maxY[i]);
        root = {left, top, right - left, bottom - top};
        order.push_back(i);
    }
    if (!order.empty())
    {
        build(root, 0, static_cast<std::uint32_t>(order.size()), 0);
        testNode(0, pairs);
    }
    std::sort(pairs.begin(), pairs.end(),
              [](const Pair& p, const Pair& q)
              { return p.first != q.first ? p.first < q.first : p.second < q.second; });
    lastStats.pairsTested = tested;
    lastStats.pairsFound = pairs.size();
}

void QuadtreeBroadphase::drawDebug(DebugRenderer& debug) const
{
    for (const Node& node : nodes)
        debug.box(node.region, DebugRenderer::hintColor);
}

} // namespace hitbox
