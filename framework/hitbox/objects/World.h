// World.h - the four steps of collision handling for a level's objects, in one call:
//   1. reduce the checks  - layers and masks, then the broadphase (cheap boxes only);
//   2. game rules         - an optional callback can veto a pair before any exact test;
//   3. the thorough test  - the Collision facade's exact test for the two shapes;
//   4. resolve            - collisionResponse(other) on both objects, then the contact
//                           events (enter, stay, exit: ContactEvent.h), then, if asked,
//                           solid objects pushed apart.
//
//     hitbox::World world;                      // uses the grid, the fastest method
//     world.add(player, kPlayerLayer, kEnemyLayer | kPickupLayer);
//     world.add(coin, kPickupLayer, kPlayerLayer, hitbox::World::Shape::Circle);
//     ...in update(), after moving everything:
//     world.checkCollisions();
//
// Changing the World while it reports (from inside collisionResponse or an event):
//   - add()      the object takes part from the next checkCollisions();
//   - remove()   the object is told nothing more and handed to no one in the pairs still to
//                come this pass (the pair being reported finishes both halves); its pairs get
//                their Exit at the end of the pass;
//   - setAlive(false), setCollider(false): the same, until it is alive / a collider again;
//   - destroying an object: as remove(); an object destroyed in the middle of its pair's two
//                responses is not handed to the other one (it no longer exists).
// Every colliding pair is reported once a pass, to the two objects that collided.
// checkCollisions() from inside a response stops with a std::logic_error naming the object.
//
// The world does not own the objects; each object knows the Worlds it is in, so remove() is
// O(1) and an object destroyed while in a World takes itself out. An object must stay at its
// address while in a World (keep objects in std::unique_ptr, or a container that does not
// move them): a copy is a new object that is in no World. Dead objects and objects that are
// not colliders are skipped (they stay in the world and come back when alive again).
#pragma once

#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/broadphase/GridBroadphase.h"
#include "hitbox/objects/ContactEvent.h"
#include "hitbox/objects/ShapeTable.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hitbox
{
class GameObject;

class World
{
public:
    // Which exact test an object takes part in: its collision box, its bounding circle, or
    // another kind of the world's ShapeTable (ShapeTable.h: the test for every pair of kinds).
    using Shape = ShapeKind;
    // How an object takes part in resolving:
    //   Moving  - solid: pushed apart from other solid objects when setPushApart(true);
    //   Fixed   - solid, never moved (a wall): the Moving object is pushed the whole way;
    //   Trigger - a sensor: collides, responds and gets events, but is never pushed and never
    //             pushes (events carry trigger == true).
    enum class Body
    {
        Moving,
        Fixed,
        Trigger
    };
    // Return false to skip a pair (checked after layers and masks, before the exact test).
    using PairRule = std::function<bool(const GameObject&, const GameObject&)>;

    // An empty world that finds its candidate pairs with `method` and tests them with
    // `shapes` (Hitbox's Box and Circle by default). A table with a pair of kinds and no test
    // between them is refused with std::invalid_argument.
    explicit World(BroadphaseMethod method = BroadphaseMethod::Grid,
                   ShapeTable shapes = ShapeTable::standard());
    // Every object still in the world is taken out (no events: the world is gone).
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    // The objects move to the new World with their contacts (not from inside a pass).
    World(World&& other) noexcept;
    World& operator=(World&& other) noexcept;

    // `layer`: the bits this object is on; `mask`: the layers it collides with. Two objects
    // are tested only if each one's layer is in the other's mask. Adding twice updates them
    // (from inside a pass: after it). O(1). A shape kind not in the world's ShapeTable is
    // refused with std::invalid_argument.
    void add(GameObject& object, std::uint32_t layer = 1, std::uint32_t mask = 0xFFFFFFFF,
             Shape shape = Shape::Box, Body body = Body::Moving);
    // Takes the object out (nothing happens if it is not in); its pairs get their Exit at
    // once (inside a pass: at the end of the pass). O(1) amortised. clear() takes all out.
    void remove(const GameObject& object);
    void clear();
    // How many objects were added and not removed.
    [[nodiscard]] std::size_t size() const { return liveCount; }
    // Is `object` in this world (added, not removed)?
    [[nodiscard]] bool contains(const GameObject& object) const;

    // The game rule every pair passes before its exact test (an empty rule allows all).
    void setRule(PairRule rule);
    // Another broadphase: same pairs found, other speed.
    void setMethod(BroadphaseMethod method);
    [[nodiscard]] BroadphaseMethod getMethod() const { return method; }
    // The grid's settings (GridBroadphase.h: cell size, threads, pair order), used whenever
    // the method is Grid, now and after a later setMethod(Grid). The default cell size, 0,
    // works it out from the boxes every step (GridCellRule.h); a cell size that is 0 or
    // less, or NaN, does the same; one too small for the boxes' spread is grown by the grid
    // (never more than a few cells per box). Same pairs whatever the settings, other speed.
    void setGridSettings(const GridSettings& settings);
    [[nodiscard]] const GridSettings& getGridSettings() const { return gridSettings; }
    // true: after a colliding pair's responses, two solid objects (Moving or Fixed, neither a
    // Trigger) still colliding are pushed apart along the contact normal - half each when
    // both are Moving, all of it on the Moving one against a Fixed one. Off by default: the
    // responses decide what happens.
    void setPushApart(bool push) { pushApart = push; }

    // Finds every colliding pair, calls first.collisionResponse(&second) and
    // second.collisionResponse(&first) for each, in the order objects were added, then the
    // contact events, and returns how many pairs collided. Responses that move objects do
    // not change which pairs this call found (the boxes were read first), but later exact
    // tests see the move. One call is one step of the events.
    std::size_t checkCollisions(); // an action (one step of events): its count may be ignored

    // The pairs that collided in the last checkCollisions() (a pointer becomes nullptr when
    // its object is destroyed).
    [[nodiscard]] const std::vector<std::pair<GameObject*, GameObject*>>& getCollisions() const
    {
        return collisions;
    }
    // The enter/stay/exit events of the last checkCollisions(), in the order they were told,
    // plus the exits from remove()/destruction since (cleared at the start of each call).
    [[nodiscard]] const std::vector<PairEvent>& getEvents() const { return events; }
    // The latest Enter or Exit (of the last 16) whose two objects still exist: the pair "that
    // changed", which the debug overlay explains. Both pointers nullptr when there is none.
    [[nodiscard]] PairEvent getLastChange() const;
    // Which exact test `object` takes part in (Box when it is not in this world).
    [[nodiscard]] Shape getShape(const GameObject& object) const;
    // The table of shape kinds and tests this world uses (for the debug renderer).
    [[nodiscard]] const ShapeTable& getShapes() const { return shapes; }
    // How many checkCollisions() calls so far (the step events are stamped with).
    [[nodiscard]] std::uint64_t getStep() const { return step; }
    // What the broadphase did last time, and how many exact tests followed.
    [[nodiscard]] BroadphaseStats getBroadphaseStats() const;
    [[nodiscard]] std::size_t getExactTests() const { return exactTests; }
    // The broadphase's picture: grid cells, quadtree nodes or the sweep axis (for
    // debug/BroadphaseDrawing.h).
    [[nodiscard]] BroadphaseLayout getBroadphaseLayout() const;

private:
    friend class GameObject; // its destructor calls forgetDestroyed

    struct Entry
    {
        GameObject* object; // nullptr once destroyed
        std::uint32_t layer;
        std::uint32_t mask;
        Shape shape;
        Body body;
        std::uint64_t serial;       // never reused: names the entry in `contacts`
        std::uint32_t contactCount; // records in `contacts` this entry is part of
        bool leaving;               // removed or destroyed; gone at the next compact()
    };
    struct PairKey
    {
        std::uint64_t first;
        std::uint64_t second;
        [[nodiscard]] bool operator==(const PairKey& other) const
        {
            return first == other.first && second == other.second;
        }
    };
    struct PairKeyHash
    {
        [[nodiscard]] std::size_t operator()(const PairKey& key) const;
    };
    // A pair that collided in some step and has not had its Exit yet.
    struct ContactRecord
    {
        std::uint32_t first; // index into entries
        std::uint32_t second;
        Contact contact; // out of second towards first
        bool trigger;
        std::uint64_t lastStep;
    };
    struct PendingUpdate
    {
        std::uint32_t index;
        std::uint32_t layer;
        std::uint32_t mask;
        Shape shape;
        Body body;
    };

    [[nodiscard]] Contact exactContact(const Entry& first, const Entry& second) const;
    [[nodiscard]] bool takesPart(std::uint32_t index) const;
    void respond(std::uint32_t first, std::uint32_t second);
    void tell(const ContactRecord& record, ContactPhase phase);
    void separate(std::uint32_t first, std::uint32_t second);
    void leave(std::uint32_t index);
    void forgetDestroyed(const GameObject& object);
    void settle();
    void compact();
    void takeFrom(World& other) noexcept; // the move: its objects now point here
    // A broadphase of `method`, the grid with gridSettings.
    [[nodiscard]] std::unique_ptr<Broadphase> newBroadphase() const;

    BroadphaseMethod method;
    GridSettings gridSettings;
    ShapeTable shapes;
    std::unique_ptr<Broadphase> broadphase;
    std::vector<Entry> entries; // in the order added; leaving entries until settle()
    std::size_t liveCount = 0;
    std::size_t leavingCount = 0;
    bool leftWithContacts = false; // an entry left while in a contact: settle() exits it
    std::uint64_t nextSerial = 0;
    std::uint64_t step = 0;
    bool busy = false; // inside checkCollisions or settle: changes are only marked
    const GameObject* responding = nullptr; // whose response runs (for messages)
    bool pushApart = false;
    PairRule rule;
    std::unordered_map<PairKey, ContactRecord, PairKeyHash> contacts;
    std::vector<PendingUpdate> pendingUpdates;
    std::vector<PairEvent> events;
    std::vector<PairEvent> recentChanges; // the last 16 Enter/Exit events, oldest first
    // Reused every call, so a steady game does not allocate.
    std::vector<BroadphaseItem> items;
    std::vector<std::uint32_t> itemEntry; // items[k] is entries[itemEntry[k]]
    std::vector<Pair> pairs;
    std::vector<std::pair<GameObject*, GameObject*>> collisions;
    std::vector<ContactRecord> exits;
    std::size_t exactTests = 0;
};

} // namespace hitbox
