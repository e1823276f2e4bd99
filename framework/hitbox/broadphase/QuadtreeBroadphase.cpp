#include "hitbox/broadphase/QuadtreeBroadphase.h"

#include <algorithm>

namespace hitbox
{

QuadtreeBroadphase::QuadtreeBroadphase(std::size_t capacity, int depth)
    : nodeCapacity(capacity), maxDepth(depth)
{
}

std::int32_t QuadtreeBroadphase::build(const Bounds& region, const Bounds& loose,
                                       std::uint32_t begin, std::uint32_t end, int depth)
{
    const std::int32_t index = static_cast<std::int32_t>(nodes.size());
    nodes.push_back(Node{region, loose, begin, end, {-1, -1, -1, -1}});
    if (end - begin <= nodeCapacity || depth >= maxDepth)
        return index; // a leaf: all its boxes stay here

    const float midX = region.minX + (region.maxX - region.minX) / 2.f;
    const float midY = region.minY + (region.maxY - region.minY) / 2.f;
    Bounds quarters[4] = {{region.minX, region.minY, midX, midY},
                          {midX, region.minY, region.maxX, midY},
                          {region.minX, midY, midX, region.maxY},
                          {midX, midY, region.maxX, region.maxY}};
    Bounds looseQuarters[4];
    for (int q = 0; q < 4; ++q)
    {
        // Grown by half the quarter's size each side, but never beyond this node's own loose
        // area, so a node's area always holds its children's (the search relies on it).
        const float growX = (quarters[q].maxX - quarters[q].minX) / 2.f;
        const float growY = (quarters[q].maxY - quarters[q].minY) / 2.f;
        looseQuarters[q] = {std::max(quarters[q].minX - growX, loose.minX),
                            std::max(quarters[q].minY - growY, loose.minY),
                            std::min(quarters[q].maxX + growX, loose.maxX),
                            std::min(quarters[q].maxY + growY, loose.maxY)};
    }
    // [slide:quadtree-insert]
    // Which quarter? The one holding the box's centre. The box goes down only if it fits
    // inside that quarter's loose area (the quarter grown by half its size on every side);
    // a box too big for it stays in this node. Every box is then inside its node's loose area.
    auto quarterOf = [&](std::uint32_t item)
    {
        const float centerX = boxes.minX[item] / 2.f + boxes.maxX[item] / 2.f;
        const float centerY = boxes.minY[item] / 2.f + boxes.maxY[item] / 2.f;
        const int q = (centerX < midX ? 0 : 1) + (centerY < midY ? 0 : 2);
        const Bounds& area = looseQuarters[q];
        const bool fits = boxes.minX[item] >= area.minX && boxes.maxX[item] <= area.maxX &&
                          boxes.minY[item] >= area.minY && boxes.maxY[item] <= area.maxY;
        return fits ? q : -1; // -1: stays here
    };
    std::uint32_t* cursor = order.data() + begin;
    std::uint32_t* last = order.data() + end;
    // Boxes that stay move to the front: they are this node's own boxes.
    cursor = std::partition(cursor, last, [&](std::uint32_t item) { return quarterOf(item) < 0; });
    nodes[index].itemsEnd = static_cast<std::uint32_t>(cursor - order.data());
    for (int q = 0; q < 4; ++q)
    {
        std::uint32_t* childEnd =
            std::partition(cursor, last, [&](std::uint32_t item) { return quarterOf(item) == q; });
        if (childEnd != cursor)
        {
            const std::int32_t child = build(
                quarters[q], looseQuarters[q], static_cast<std::uint32_t>(cursor - order.data()),
                static_cast<std::uint32_t>(childEnd - order.data()), depth + 1);
            nodes[index].children[q] = child; // not a reference: build() grew `nodes`
        }
        cursor = childEnd;
    }
    // [/slide]
    return index;
}

void QuadtreeBroadphase::findPairsOf(std::uint32_t a, std::vector<Pair>& pairs)
{
    // Walk down from the root, into every node whose loose area touches box a: any box that
    // overlaps a is inside the loose area of its node, so that node is visited.
    stack.clear();
    stack.push_back(0);
    while (!stack.empty())
    {
        const Node& node = nodes[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        for (std::uint32_t k = node.itemsBegin; k < node.itemsEnd; ++k)
        {
            const std::uint32_t b = order[k];
            // Each pair once: the box with the lower index reports it.
            if (b <= a || !boxes.allowed(a, b))
                continue;
            ++tested;
            if (boxes.overlap(a, b))
                pairs.push_back({a, b});
        }
        for (const std::int32_t child : node.children)
        {
            if (child < 0)
                continue;
            const Bounds& area = nodes[static_cast<std::size_t>(child)].loose;
            if (area.minX <= boxes.maxX[a] && boxes.minX[a] <= area.maxX &&
                area.minY <= boxes.maxY[a] && boxes.minY[a] <= area.maxY)
                stack.push_back(child);
        }
    }
}

void QuadtreeBroadphase::findPairs(const std::vector<BroadphaseItem>& items,
                                   std::vector<Pair>& pairs)
{
    pairs.clear();
    nodes.clear();
    tested = 0;
    boxes.load(items);

    // The root covers every usable box exactly; NaN boxes are left out of the tree.
    order.clear();
    Bounds root{0.f, 0.f, 0.f, 0.f};
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
    {
        if (!boxes.isUsable(i))
            continue;
        if (order.empty())
            root = {boxes.minX[i], boxes.minY[i], boxes.maxX[i], boxes.maxY[i]};
        root = {std::min(root.minX, boxes.minX[i]), std::min(root.minY, boxes.minY[i]),
                std::max(root.maxX, boxes.maxX[i]), std::max(root.maxY, boxes.maxY[i])};
        order.push_back(i);
    }
    if (order.empty())
    {
        lastStats = {};
        return;
    }
    build(root, root, 0, static_cast<std::uint32_t>(order.size()), 0);
    for (std::uint32_t a = 0; a < boxes.size(); ++a)
    {
        if (!boxes.isUsable(a))
            continue;
        const std::size_t firstOfA = pairs.size();
        findPairsOf(a, pairs);
        // a's pairs come out in tree order: put them in order of `second`.
        std::sort(pairs.begin() + static_cast<std::ptrdiff_t>(firstOfA), pairs.end(),
                  [](const Pair& p, const Pair& q) { return p.second < q.second; });
    }
    lastStats.pairsTested = tested;
    lastStats.pairsFound = pairs.size();
}

BroadphaseLayout QuadtreeBroadphase::layout() const
{
    BroadphaseLayout result;
    for (const Node& node : nodes)
        result.nodes.push_back({node.region.minX, node.region.minY,
                                node.region.maxX - node.region.minX,
                                node.region.maxY - node.region.minY});
    return result;
}

} // namespace hitbox
