#include "hitbox/objects/WorldLinks.h"

namespace hitbox
{

WorldLink* WorldLinks::find(const World* world)
{
    if (world == nullptr)
        return nullptr;
    if (first.world == world)
        return &first;
    for (WorldLink& link : more)
        if (link.world == world)
            return &link;
    return nullptr;
}

void WorldLinks::set(World* world, std::uint32_t index)
{
    if (WorldLink* link = find(world))
        link->index = index;
    else if (first.world == nullptr)
        first = {world, index};
    else
        more.push_back({world, index});
}

void WorldLinks::erase(const World* world)
{
    if (first.world == world)
    {
        first = {};
        if (!more.empty())
        {
            first = more.back();
            more.pop_back();
        }
        return;
    }
    for (std::size_t i = 0; i < more.size(); ++i)
    {
        if (more[i].world == world)
        {
            more[i] = more.back();
            more.pop_back();
            return;
        }
    }
}

std::vector<World*> WorldLinks::worlds() const
{
    std::vector<World*> all;
    if (first.world != nullptr)
        all.push_back(first.world);
    for (const WorldLink& link : more)
        all.push_back(link.world);
    return all;
}

} // namespace hitbox
