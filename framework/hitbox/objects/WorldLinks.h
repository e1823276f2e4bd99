// WorldLinks.h - which Worlds an object is in, kept inside the object, so a World can take an
// object out in O(1) and an object destroyed while still in a World takes itself out.
//
// Copying gives an empty set: a copy is a new object that no World has been told about
// (World.h). Plain data, no SFML.
#pragma once

#include <cstdint>
#include <vector>

namespace hitbox
{

class World;

// One World the object is in, and where its entry sits in that World's list.
struct WorldLink
{
    World* world = nullptr;
    std::uint32_t index = 0;
};

class WorldLinks
{
public:
    WorldLinks() = default;
    // A copy is in no World; assigning keeps the Worlds this object is already in.
    WorldLinks(const WorldLinks&) {}
    WorldLinks& operator=(const WorldLinks&) { return *this; }
    ~WorldLinks() = default;

    // The link to `world`, or nullptr when the object is not in it.
    [[nodiscard]] WorldLink* find(const World* world);
    // Records that the object is in `world` at `index` (or moves it to `index`).
    void set(World* world, std::uint32_t index);
    // Forgets `world` (nothing happens if the object is not in it).
    void erase(const World* world);
    // Every World the object is in (most objects: none or one).
    [[nodiscard]] std::vector<World*> worlds() const;

private:
    WorldLink first;             // no allocation for the usual case: one World
    std::vector<WorldLink> more; // a second World and beyond
};

} // namespace hitbox
