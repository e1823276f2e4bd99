// TEMPORARY STAND-IN (see Broadphase.h): brute force under every name.
#include "hitbox/broadphase/Broadphase.h"

#include "hitbox/geometry/Overlap.h"

namespace hitbox
{
namespace
{

class StandIn : public Broadphase
{
public:
    explicit StandIn(BroadphaseMethod method) : method(method) {}

    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override
    {
        pairs.clear();
        counts = {};
        const auto count = static_cast<std::uint32_t>(items.size());
        for (std::uint32_t i = 0; i < count; ++i)
            for (std::uint32_t j = i + 1; j < count; ++j)
            {
                const BroadphaseItem& a = items[i];
                const BroadphaseItem& b = items[j];
                if (!((a.layer & b.mask) && (b.layer & a.mask)))
                    continue;
                ++counts.pairsTested;
                if (boxVsBox(a.box, b.box))
                    pairs.push_back({i, j});
            }
        counts.pairsFound = pairs.size();
    }
    const char* name() const override { return toString(method); }
    BroadphaseStats stats() const override { return counts; }
    void drawDebug(DebugRenderer&) const override {}

private:
    BroadphaseMethod method;
    BroadphaseStats counts;
};

} // namespace

std::unique_ptr<Broadphase> makeBroadphase(BroadphaseMethod method)
{
    return std::make_unique<StandIn>(method);
}

const char* toString(BroadphaseMethod method)
{
    switch (method)
    {
    case BroadphaseMethod::BruteForce:
        return "brute force";
    case BroadphaseMethod::SortAndSweep:
        return "sort and sweep";
    case BroadphaseMethod::Grid:
        return "grid";
    case BroadphaseMethod::Quadtree:
        return "quadtree";
    }
    return "?";
}

} // namespace hitbox
