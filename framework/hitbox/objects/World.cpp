#include "hitbox/objects/World.h"

#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"

#include <algorithm>

namespace hitbox
{
namespace
{

// The box the broadphase sees: it must contain the shape the exact test uses.
Box boundsOf(GameObject& object, World::Shape shape)
{
    if (shape == World::Shape::Box)
        return toBox(object.getCollisionBox());
    const Circle circle = object.getBoundingCircle();
    return {circle.center.x - circle.radius, circle.center.y - circle.radius, 2.f * circle.radius,
            2.f * circle.radius};
}

} // namespace

World::World(BroadphaseMethod chosen) : method(chosen), broadphase(makeBroadphase(chosen)) {}

void World::add(GameObject& object, std::uint32_t layer, std::uint32_t mask, Shape shape)
{
    for (Entry& entry : entries)
    {
        if (entry.object == &object)
        {
            entry = {&object, layer, mask, shape};
            return;
        }
    }
    entries.push_back({&object, layer, mask, shape});
}

void World::remove(const GameObject& object)
{
    entries.erase(std::remove_if(entries.begin(), entries.end(),
                                 [&](const Entry& entry) { return entry.object == &object; }),
                  entries.end());
}

void World::clear()
{
    entries.clear();
    collisions.clear();
}

void World::setRule(PairRule newRule)
{
    rule = std::move(newRule);
}

void World::setMethod(BroadphaseMethod newMethod)
{
    method = newMethod;
    broadphase = makeBroadphase(newMethod);
}

BroadphaseStats World::getBroadphaseStats() const
{
    return broadphase->stats();
}

BroadphaseLayout World::getBroadphaseLayout() const
{
    return broadphase->layout();
}

bool World::exactTest(const Entry& first, const Entry& second) const
{
    if (first.shape == Shape::Box && second.shape == Shape::Box)
        return Collision::checkBoundingBox(first.object, second.object);
    if (first.shape == Shape::Circle && second.shape == Shape::Circle)
        return Collision::checkBoundingCircle(first.object, second.object);
    if (first.shape == Shape::Circle)
        return Collision::checkCircleBox(first.object, second.object);
    return Collision::checkCircleBox(second.object, first.object);
}

std::size_t World::checkCollisions()
{
    // Step 1: only live colliders go to the broadphase, as boxes with their layers.
    items.clear();
    itemEntry.clear();
    for (std::uint32_t e = 0; e < entries.size(); ++e)
    {
        GameObject& object = *entries[e].object;
        if (!object.isAlive() || !object.isCollider())
            continue;
        items.push_back({boundsOf(object, entries[e].shape), entries[e].layer, entries[e].mask});
        itemEntry.push_back(e);
    }
    broadphase->findPairs(items, pairs);

    collisions.clear();
    exactTests = 0;
    for (const Pair& pair : pairs)
    {
        const Entry& first = entries[itemEntry[pair.first]];
        const Entry& second = entries[itemEntry[pair.second]];
        // Step 2: game rules, before paying for the exact test.
        if (rule && !rule(*first.object, *second.object))
            continue;
        // Step 3: the exact test (it also re-checks alive/collider: a response may have
        // killed one of them earlier in this loop).
        ++exactTests;
        if (!exactTest(first, second))
            continue;
        // Step 4: both objects respond, each told what it hit.
        collisions.emplace_back(first.object, second.object);
        first.object->collisionResponse(second.object);
        second.object->collisionResponse(first.object);
    }
    return collisions.size();
}

} // namespace hitbox
