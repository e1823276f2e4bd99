#include "Scenes.h"

#include "hitbox/geometry/Overlap.h"

#include <cmath>
#include <limits>

namespace scenes
{
namespace
{

float uniform(std::mt19937& random, float low, float high)
{
    return std::uniform_real_distribution<float>(low, high)(random);
}

int integer(std::mt19937& random, int low, int high)
{
    return std::uniform_int_distribution<int>(low, high)(random);
}

hitbox::Box ordinaryBox(std::mt19937& random)
{
    const float side = uniform(random, 8.f, 32.f); // sizes vary x4, like the benchmark
    return {uniform(random, 0.f, 1200.f), uniform(random, 0.f, 675.f), side,
            side * uniform(random, 0.5f, 2.f)};
}

} // namespace

std::string describe(Kind kind)
{
    const char* names[] = {"Scattered", "OnGridLines", "BigAndSmall",  "FarAndHuge",
                           "ZeroSize",  "OneSpot",     "NegativeSize", "WithNaN"};
    return names[static_cast<int>(kind)];
}

std::vector<hitbox::BroadphaseItem> make(Kind kind, std::size_t count, bool useLayers,
                                         std::mt19937& random)
{
    const float notANumber = std::numeric_limits<float>::quiet_NaN();
    const float infinite = std::numeric_limits<float>::infinity();
    std::vector<hitbox::BroadphaseItem> items(count);
    for (hitbox::BroadphaseItem& item : items)
    {
        hitbox::Box box = ordinaryBox(random);
        switch (kind)
        {
        case Kind::Scattered:
            break;
        case Kind::OnGridLines:
            // A small world on an 8-pixel lattice: many boxes touch exactly, many edges lie
            // on cell boundaries of a grid whose cells are multiples of 8.
            box = {8.f * integer(random, -4, 12), 8.f * integer(random, -4, 12),
                   8.f * integer(random, 0, 4), 8.f * integer(random, 0, 4)};
            break;
        case Kind::BigAndSmall:
            if (integer(random, 0, 9) == 0)
                box = {uniform(random, -200.f, 1000.f), uniform(random, -200.f, 600.f),
                       uniform(random, 200.f, 1500.f), uniform(random, 200.f, 900.f)};
            break;
        case Kind::FarAndHuge:
        {
            const float scales[] = {1.f, 1e4f, 1e8f, 1e20f, 1e37f};
            const float scale = scales[integer(random, 0, 4)];
            box = {uniform(random, -1.f, 1.f) * scale, uniform(random, -1.f, 1.f) * scale,
                   uniform(random, 0.f, 1.f) * scale, uniform(random, 0.f, 1.f) * scale};
            if (integer(random, 0, 19) == 0)
                box = {-3e38f, -3e38f, 3.4e38f, 3.4e38f}; // reaches across half of all floats
            else if (integer(random, 0, 19) == 0)
                box = {3e38f, -1e38f, 3e38f, 3e38f}; // left + width overflows to infinity
            break;
        }
        case Kind::ZeroSize:
            if (integer(random, 0, 1) == 0)
            {
                box.left = 8.f * integer(random, 0, 20);
                box.top = 8.f * integer(random, 0, 20);
                box.width = integer(random, 0, 2) == 0 ? 0.f : 8.f * integer(random, 0, 3);
                box.height = integer(random, 0, 2) == 0 ? 0.f : 8.f * integer(random, 0, 3);
                if (integer(random, 0, 1) == 0)
                    box.width = 0.f;
            }
            else
            {
                box = {8.f * integer(random, 0, 20), 8.f * integer(random, 0, 20), 16.f, 16.f};
            }
            break;
        case Kind::OneSpot:
            box = integer(random, 0, 4) == 0 ? hitbox::Box{100.f, 100.f, 0.f, 0.f}
                                             : hitbox::Box{100.f, 100.f, 20.f, 20.f};
            break;
        case Kind::NegativeSize:
            if (integer(random, 0, 1) == 0)
                box.width = -box.width;
            if (integer(random, 0, 1) == 0)
                box.height = -box.height;
            break;
        case Kind::WithNaN:
        {
            const int which = integer(random, 0, 7);
            if (which == 0)
                box.left = notANumber;
            else if (which == 1)
                box.height = notANumber;
            else if (which == 2)
                box.width = infinite;
            else if (which == 3)
                box.top = -infinite;
            break;
        }
        case Kind::Count:
            break;
        }
        item.box = box;
        if (useLayers)
        {
            item.layer = 1u << integer(random, 0, 3);
            item.mask = static_cast<std::uint32_t>(integer(random, 0, 15));
        }
    }
    return items;
}

void move(std::vector<hitbox::BroadphaseItem>& items, bool teleport, std::mt19937& random)
{
    for (hitbox::BroadphaseItem& item : items)
    {
        if (!std::isfinite(item.box.left) || !std::isfinite(item.box.top))
            continue;
        if (teleport && integer(random, 0, 3) == 0)
        {
            // Far across the world (or beyond it): last frame's order is no help at all.
            item.box.left = uniform(random, -5000.f, 5000.f);
            item.box.top = uniform(random, -5000.f, 5000.f);
            continue;
        }
        // Half the moves land on the 8-pixel lattice so exact touching keeps happening.
        if (integer(random, 0, 1) == 0)
        {
            item.box.left += uniform(random, -6.f, 6.f);
            item.box.top += uniform(random, -6.f, 6.f);
        }
        else
        {
            item.box.left += 8.f * integer(random, -1, 1);
            item.box.top += 8.f * integer(random, -1, 1);
        }
    }
}

std::vector<hitbox::Pair> referencePairs(const std::vector<hitbox::BroadphaseItem>& items)
{
    std::vector<hitbox::Pair> pairs;
    for (std::uint32_t i = 0; i < items.size(); ++i)
    {
        for (std::uint32_t j = i + 1; j < items.size(); ++j)
        {
            const bool allowed =
                (items[i].layer & items[j].mask) != 0 && (items[j].layer & items[i].mask) != 0;
            if (allowed && hitbox::boxVsBox(items[i].box, items[j].box))
                pairs.push_back({i, j});
        }
    }
    return pairs;
}

} // namespace scenes
