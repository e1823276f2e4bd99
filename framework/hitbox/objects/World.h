// World.h - the four steps of collision handling for a level's objects, in one call:
//   1. reduce the checks  - layers and masks, then the broadphase (cheap boxes only);
//   2. game rules         - an optional callback can veto a pair before any exact test;
//   3. the thorough test  - the Collision facade's exact test for the two shapes;
//   4. resolve            - collisionResponse(other) on both objects.
//
//     hitbox::World world;                      // uses the grid, the fastest method
//     world.add(player, kPlayerLayer, kEnemyLayer | kPickupLayer);
//     world.add(coin, kPickupLayer, kPlayerLayer, hitbox::World::Shape::Circle);
//     ...in update(), after moving everything:
//     world.checkCollisions();
//
// The world does not own the objects: remove() one before it is destroyed. Dead objects and
// objects that are not colliders are skipped (they stay in the world and come back when
// alive again).
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

class GameObject;

namespace hitbox
{

class World
{
public:
    // Which exact test an object takes part in: its collision box or its bounding circle.
    // A circle meets a box with Collision::checkCircleBox.
    enum class Shape
    {
        Box,
        Circle
    };
    // Return false to skip a pair (checked after layers and masks, before the exact test).
    using PairRule = std::function<bool(const GameObject&, const GameObject&)>;

    // An empty world that finds its candidate pairs with `method`.
    explicit World(BroadphaseMethod method = BroadphaseMethod::Grid);

    // `layer`: the bits this object is on; `mask`: the layers it collides with. Two objects
    // are tested only if each one's layer is in the other's mask. Adding twice updates them.
    void add(GameObject& object, std::uint32_t layer = 1, std::uint32_t mask = 0xFFFFFFFF,
             Shape shape = Shape::Box);
    // Takes the object out (nothing happens if it is not in). clear() takes all out.
    void remove(const GameObject& object);
    void clear();
    // How many objects were added and not removed.
    std::size_t size() const { return entries.size(); }

    // The game rule every pair passes before its exact test (an empty rule allows all).
    void setRule(PairRule rule);
    // Another broadphase: same pairs found, other speed.
    void setMethod(BroadphaseMethod method);
    BroadphaseMethod getMethod() const { return method; }

    // Finds every colliding pair, calls first.collisionResponse(&second) and
    // second.collisionResponse(&first) for each, in the order objects were added, and
    // returns how many pairs collided. Responses that move objects do not change which
    // pairs this call found (the boxes were read first), but later exact tests see the move.
    std::size_t checkCollisions();

    // The pairs that collided in the last checkCollisions().
    const std::vector<std::pair<GameObject*, GameObject*>>& getCollisions() const
    {
        return collisions;
    }
    // What the broadphase did last time, and how many exact tests followed.
    BroadphaseStats getBroadphaseStats() const;
    std::size_t getExactTests() const { return exactTests; }
    // The broadphase's picture: grid cells, quadtree nodes or the sweep axis (for
    // debug/BroadphaseDrawing.h).
    BroadphaseLayout getBroadphaseLayout() const;

private:
    struct Entry
    {
        GameObject* object;
        std::uint32_t layer;
        std::uint32_t mask;
        Shape shape;
    };
    bool exactTest(const Entry& first, const Entry& second) const;

    BroadphaseMethod method;
    std::unique_ptr<Broadphase> broadphase;
    std::vector<Entry> entries;
    PairRule rule;
    // Reused every call, so a steady game does not allocate.
    std::vector<BroadphaseItem> items;
    std::vector<std::uint32_t> itemEntry; // items[k] is entries[itemEntry[k]]
    std::vector<Pair> pairs;
    std::vector<std::pair<GameObject*, GameObject*>> collisions;
    std::size_t exactTests = 0;
};

} // namespace hitbox
