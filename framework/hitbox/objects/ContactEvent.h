// ContactEvent.h - enter, stay and exit: what a World tells a pair of objects step by step,
// beside collisionResponse (the names Unity's OnCollisionEnter2D/Stay/Exit and Box2D v3's
// begin/end touch events made familiar).
//
//   Enter - the first step the two collide (share area; touching is not colliding).
//   Stay  - every further step they still collide.
//   Exit  - the first step they no longer collide, or the first moment one of them leaves
//           the World, is destroyed, is killed (setAlive(false)), stops being a collider, or
//           a game rule skips the pair. Every Enter is followed by exactly one Exit.
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <cstdint>

namespace hitbox
{
class GameObject;

enum class ContactPhase
{
    Enter,
    Stay,
    Exit
};

// "enter", "stay" or "exit".
[[nodiscard]] const char* toString(ContactPhase phase);

// What one object of a pair is told (GameObject::onCollisionEnter/Stay/Exit).
struct CollisionEvent
{
    ContactPhase phase = ContactPhase::Enter;
    // The other object of the pair; nullptr only when it was destroyed (an Exit).
    GameObject* other = nullptr;
    // normal points out of `other` towards the object told; depth > 0. For an Exit: the
    // last contact the pair had while colliding.
    Contact contact;
    bool trigger = false;   // one of the two is a trigger (sensor): reported, never pushed
    std::uint64_t step = 0; // the World's step (checkCollisions call) it happened in
};

// The same event for the pair, as the World lists it (World::getEvents()).
struct PairEvent
{
    ContactPhase phase = ContactPhase::Enter;
    GameObject* first = nullptr;  // nullptr only when destroyed (an Exit)
    GameObject* second = nullptr; // nullptr only when destroyed (an Exit)
    Contact contact;              // normal out of `second` towards `first`
    bool trigger = false;
    std::uint64_t step = 0;
};

} // namespace hitbox
