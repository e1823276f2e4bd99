#include "hitbox/objects/World.h"

#include "hitbox/objects/GameObject.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace hitbox
{
namespace
{

// Sets a flag for as long as it lives, so an exception from a response cannot leave the
// World thinking it is still inside a pass.
class BusyGuard
{
public:
    explicit BusyGuard(bool& flag) : flag(flag) { flag = true; }
    ~BusyGuard() { flag = false; }
    BusyGuard(const BusyGuard&) = delete;
    BusyGuard& operator=(const BusyGuard&) = delete;

private:
    bool& flag;
};

const std::uint32_t noIndex = std::numeric_limits<std::uint32_t>::max();

} // namespace

std::size_t World::PairKeyHash::operator()(const PairKey& key) const
{
    // Serials are small counters: mixing them like boost::hash_combine spreads them well.
    const std::size_t a = std::hash<std::uint64_t>{}(key.first);
    const std::size_t b = std::hash<std::uint64_t>{}(key.second);
    return a ^ (b + 0x9e3779b97f4a7c15ull + (a << 6) + (a >> 2));
}

World::World(BroadphaseMethod chosen, ShapeTable table)
    : method(chosen), shapes(table), broadphase(newBroadphase())
{
    if (!shapes.isComplete())
        throw std::invalid_argument("hitbox::World: its ShapeTable has a pair of shape kinds "
                                    "with no test between them (ShapeTable::setTest)");
}

World::~World()
{
    for (Entry& entry : entries)
        if (entry.object != nullptr)
            entry.object->worlds.erase(this);
}

World::World(World&& other) noexcept
{
    takeFrom(other);
}

World& World::operator=(World&& other) noexcept
{
    if (this != &other)
    {
        for (Entry& entry : entries)
            if (entry.object != nullptr)
                entry.object->worlds.erase(this);
        takeFrom(other);
    }
    return *this;
}

void World::takeFrom(World& other) noexcept
{
    method = other.method;
    gridSettings = other.gridSettings;
    shapes = other.shapes;
    broadphase = std::move(other.broadphase);
    other.broadphase = other.newBroadphase();
    entries = std::move(other.entries);
    other.entries.clear();
    liveCount = std::exchange(other.liveCount, 0);
    leavingCount = std::exchange(other.leavingCount, 0);
    leftWithContacts = std::exchange(other.leftWithContacts, false);
    nextSerial = other.nextSerial;
    step = other.step;
    pushApart = other.pushApart;
    rule = std::move(other.rule);
    contacts = std::move(other.contacts);
    other.contacts.clear();
    pendingUpdates = std::move(other.pendingUpdates);
    events = std::move(other.events);
    recentChanges = std::move(other.recentChanges);
    collisions = std::move(other.collisions);
    exactTests = other.exactTests;
    for (std::uint32_t index = 0; index < entries.size(); ++index)
    {
        if (GameObject* object = entries[index].object)
        {
            object->worlds.erase(&other);
            object->worlds.set(this, index);
        }
    }
}

void World::add(GameObject& object, std::uint32_t layer, std::uint32_t mask, Shape shape, Body body)
{
    if (!shapes.has(shape))
        throw std::invalid_argument("hitbox::World::add: " + object.describe() +
                                    " has shape kind " + std::to_string(static_cast<int>(shape)) +
                                    ", which is not in the world's ShapeTable");
    if (WorldLink* link = object.worlds.find(this))
    {
        Entry& entry = entries[link->index];
        if (entry.leaving) // removed earlier in this pass, or not yet compacted: back in
        {
            entry.leaving = false;
            --leavingCount;
            ++liveCount;
        }
        if (busy)
            pendingUpdates.push_back({link->index, layer, mask, shape, body});
        else
        {
            entry.layer = layer;
            entry.mask = mask;
            entry.shape = shape;
            entry.body = body;
        }
        return;
    }
    if (entries.size() >= noIndex)
        throw std::length_error("hitbox::World: more than 4,294,967,294 objects");
    entries.push_back({&object, layer, mask, shape, body, nextSerial++, 0, false});
    object.worlds.set(this, static_cast<std::uint32_t>(entries.size() - 1));
    ++liveCount;
}

PairEvent World::getLastChange() const
{
    for (auto it = recentChanges.rbegin(); it != recentChanges.rend(); ++it)
        if (it->first != nullptr && it->second != nullptr)
            return *it;
    return {};
}

World::Shape World::getShape(const GameObject& object) const
{
    const WorldLink* link = object.worlds.find(this);
    return link != nullptr ? entries[link->index].shape : Shape::Box;
}

bool World::contains(const GameObject& object) const
{
    const WorldLink* link = object.worlds.find(this);
    return link != nullptr && !entries[link->index].leaving;
}

void World::leave(std::uint32_t index)
{
    Entry& entry = entries[index];
    if (entry.leaving)
        return;
    entry.leaving = true;
    --liveCount;
    ++leavingCount;
    if (entry.contactCount > 0)
        leftWithContacts = true;
}

void World::remove(const GameObject& object)
{
    const WorldLink* link = object.worlds.find(this);
    if (link == nullptr)
        return;
    leave(link->index);
    settle();
}

void World::forgetDestroyed(const GameObject& object)
{
    const WorldLink* link = object.worlds.find(this);
    if (link == nullptr)
        return;
    const std::uint32_t index = link->index;
    leave(index);
    entries[index].object = nullptr;
    object.worlds.erase(this);
    // Nothing the World hands out may point at it any more.
    for (std::pair<GameObject*, GameObject*>& pair : collisions)
    {
        if (pair.first == &object)
            pair.first = nullptr;
        if (pair.second == &object)
            pair.second = nullptr;
    }
    for (PairEvent& event : events)
    {
        if (event.first == &object)
            event.first = nullptr;
        if (event.second == &object)
            event.second = nullptr;
    }
    for (PairEvent& event : recentChanges)
    {
        if (event.first == &object)
            event.first = nullptr;
        if (event.second == &object)
            event.second = nullptr;
    }
    settle();
}

void World::clear()
{
    for (std::uint32_t index = 0; index < entries.size(); ++index)
        leave(index);
    collisions.clear();
    settle();
    if (!busy)
        compact();
}

void World::setRule(PairRule newRule)
{
    rule = std::move(newRule);
}

void World::setMethod(BroadphaseMethod newMethod)
{
    method = newMethod;
    broadphase = newBroadphase();
}

void World::setGridSettings(const GridSettings& settings)
{
    gridSettings = settings;
    if (method == BroadphaseMethod::Grid)
        broadphase = newBroadphase();
}

std::unique_ptr<Broadphase> World::newBroadphase() const
{
    if (method == BroadphaseMethod::Grid)
        return std::make_unique<GridBroadphase>(gridSettings);
    return makeBroadphase(method);
}

BroadphaseStats World::getBroadphaseStats() const
{
    return broadphase->stats();
}

BroadphaseLayout World::getBroadphaseLayout() const
{
    return broadphase->layout();
}

bool World::takesPart(std::uint32_t index) const
{
    const Entry& entry = entries[index];
    return !entry.leaving && entry.object != nullptr && entry.object->isAlive() &&
           entry.object->isCollider();
}

Contact World::exactContact(const Entry& first, const Entry& second) const
{
    // The table's test (ShapeTable.h); the bool test inside it decides the edge rule.
    return shapes.test(*first.object, first.shape, *second.object, second.shape);
}

std::size_t World::checkCollisions()
{
    if (busy)
        throw std::logic_error("hitbox::World::checkCollisions() was called from inside " +
                               (responding != nullptr
                                    ? responding->describe() + "'s collision response or event"
                                    : std::string("a collision response or event")) +
                               ": call it once a step, from the level's update()");
    settle();
    compact();
    events.clear();
    {
        const BusyGuard guard(busy);
        ++step;
        // Step 1: only live colliders go to the broadphase, as boxes with their layers.
        items.clear();
        itemEntry.clear();
        for (std::uint32_t e = 0; e < entries.size(); ++e)
        {
            if (!takesPart(e))
                continue;
            items.push_back({shapes.bounds(*entries[e].object, entries[e].shape), entries[e].layer,
                             entries[e].mask});
            itemEntry.push_back(e);
        }
        broadphase->findPairs(items, pairs);

        collisions.clear();
        exactTests = 0;
        for (const Pair& pair : pairs)
            respond(itemEntry[pair.first], itemEntry[pair.second]);

        // Every pair that collided before and not in this step exits, in the order added.
        exits.clear();
        for (auto it = contacts.begin(); it != contacts.end();)
        {
            if (it->second.lastStep != step)
            {
                exits.push_back(it->second);
                --entries[it->second.first].contactCount;
                --entries[it->second.second].contactCount;
                it = contacts.erase(it);
            }
            else
                ++it;
        }
        std::sort(exits.begin(), exits.end(),
                  [](const ContactRecord& x, const ContactRecord& y) {
                      return std::make_pair(x.first, x.second) < std::make_pair(y.first, y.second);
                  });
        const std::vector<ContactRecord> toTell = exits;
        for (const ContactRecord& record : toTell)
            tell(record, ContactPhase::Exit);
        responding = nullptr;
    }
    settle();
    return collisions.size();
}

void World::respond(std::uint32_t i, std::uint32_t j)
{
    // Entries may be appended by responses (add), so they are read by index, never held.
    if (!takesPart(i) || !takesPart(j))
        return;
    // Step 2: game rules, before paying for the exact test.
    if (rule && !rule(*entries[i].object, *entries[j].object))
        return;
    // Step 3: the exact test.
    ++exactTests;
    const Contact contact = exactContact(entries[i], entries[j]);
    if (!contact.hit)
        return;
    GameObject* a = entries[i].object;
    GameObject* b = entries[j].object;
    collisions.emplace_back(a, b);
    const bool trigger = entries[i].body == Body::Trigger || entries[j].body == Body::Trigger;
    const PairKey key{entries[i].serial, entries[j].serial};
    const auto found = contacts.try_emplace(key, ContactRecord{i, j, contact, trigger, step});
    const ContactPhase phase = found.second ? ContactPhase::Enter : ContactPhase::Stay;
    if (found.second)
    {
        ++entries[i].contactCount;
        ++entries[j].contactCount;
    }
    else
    {
        found.first->second.contact = contact;
        found.first->second.trigger = trigger;
        found.first->second.lastStep = step;
    }
    const ContactRecord record = found.first->second;
    // Step 4: both objects respond, each told what it hit. The pair's two halves both run
    // unless one of the two no longer exists.
    responding = a;
    a->collisionResponse(b);
    if (entries[i].object != nullptr && entries[j].object != nullptr)
    {
        responding = b;
        b->collisionResponse(a);
    }
    tell(record, phase);
    if (pushApart)
        separate(i, j);
}

void World::tell(const ContactRecord& record, ContactPhase phase)
{
    GameObject* a = entries[record.first].object;
    GameObject* b = entries[record.second].object;
    events.push_back({phase, a, b, record.contact, record.trigger, step});
    if (phase != ContactPhase::Stay)
    {
        if (recentChanges.size() == 16)
            recentChanges.erase(recentChanges.begin());
        recentChanges.push_back(events.back());
    }
    void (GameObject::*hook)(const CollisionEvent&) = &GameObject::onCollisionEnter;
    if (phase == ContactPhase::Stay)
        hook = &GameObject::onCollisionStay;
    else if (phase == ContactPhase::Exit)
        hook = &GameObject::onCollisionExit;
    if (a != nullptr)
    {
        responding = a;
        (a->*hook)({phase, b, record.contact, record.trigger, step});
    }
    // a's event may have destroyed either object: read both again.
    a = entries[record.first].object;
    b = entries[record.second].object;
    if (b != nullptr)
    {
        Contact flipped = record.contact;
        flipped.normal = -flipped.normal; // out of a towards b
        responding = b;
        (b->*hook)({phase, a, flipped, record.trigger, step});
    }
}

// [slide:world-trigger-never-pushed]
void World::separate(std::uint32_t i, std::uint32_t j)
{
    if (!takesPart(i) || !takesPart(j))
        return;
    const Body bodyA = entries[i].body;
    const Body bodyB = entries[j].body;
    if (bodyA == Body::Trigger || bodyB == Body::Trigger)
        return;
    const float shareA = bodyA != Body::Moving ? 0.f : (bodyB == Body::Moving ? 0.5f : 1.f);
    const float shareB = bodyB != Body::Moving ? 0.f : (bodyA == Body::Moving ? 0.5f : 1.f);
    // The responses may have moved them: measure again.
    const Contact contact = exactContact(entries[i], entries[j]);
    if (!contact.hit)
        return;
    entries[i].object->move(toSfml(contact.normal * (contact.depth * shareA)));
    entries[j].object->move(toSfml(contact.normal * (-contact.depth * shareB)));
}
// [/slide]

void World::settle()
{
    if (busy)
        return;
    {
        const BusyGuard guard(busy);
        for (const PendingUpdate& update : pendingUpdates)
        {
            Entry& entry = entries[update.index];
            entry.layer = update.layer;
            entry.mask = update.mask;
            entry.shape = update.shape;
            entry.body = update.body;
        }
        pendingUpdates.clear();
        // Pairs with an object that left get their Exit; an Exit may make more leave.
        while (leftWithContacts)
        {
            leftWithContacts = false;
            exits.clear();
            for (auto it = contacts.begin(); it != contacts.end();)
            {
                const ContactRecord& record = it->second;
                if (entries[record.first].leaving || entries[record.second].leaving)
                {
                    exits.push_back(record);
                    --entries[record.first].contactCount;
                    --entries[record.second].contactCount;
                    it = contacts.erase(it);
                }
                else
                    ++it;
            }
            std::sort(
                exits.begin(), exits.end(),
                [](const ContactRecord& x, const ContactRecord& y)
                { return std::make_pair(x.first, x.second) < std::make_pair(y.first, y.second); });
            const std::vector<ContactRecord> toTell = exits;
            for (const ContactRecord& record : toTell)
                tell(record, ContactPhase::Exit);
        }
        responding = nullptr;
    }
    // Removing is O(1) amortised: the list is compacted once half of it has left.
    if (leavingCount > liveCount)
        compact();
}

void World::compact()
{
    if (leavingCount == 0 || busy)
        return;
    std::vector<std::uint32_t> newIndex(entries.size(), noIndex);
    std::uint32_t kept = 0;
    for (std::uint32_t index = 0; index < entries.size(); ++index)
    {
        Entry& entry = entries[index];
        if (entry.leaving)
        {
            if (entry.object != nullptr)
                entry.object->worlds.erase(this);
            continue;
        }
        newIndex[index] = kept;
        entries[kept] = entry;
        entries[kept].object->worlds.set(this, kept);
        ++kept;
    }
    entries.resize(kept);
    leavingCount = 0;
    for (auto it = contacts.begin(); it != contacts.end();)
    {
        ContactRecord& record = it->second;
        record.first = newIndex[record.first];
        record.second = newIndex[record.second];
        if (record.first == noIndex || record.second == noIndex) // cannot happen after settle()
            it = contacts.erase(it);
        else
            ++it;
    }
}

} // namespace hitbox
