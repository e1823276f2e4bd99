#include "Bugs.h"

#include <cstddef>

// BEGIN TASK 1: a plate that lets go: count with enter and exit events
// The World says when something starts (Enter) and stops (Exit) colliding, also when it is
// removed or destroyed while on the plate: count who is on it, and never miss a leaver.
void PressurePlate::collisionResponse(hitbox::GameObject*) {}

void PressurePlate::onCollisionEnter(const hitbox::CollisionEvent&)
{
    ++standingOn;
}

void PressurePlate::onCollisionExit(const hitbox::CollisionEvent&)
{
    --standingOn;
}

bool PressurePlate::isPressed() const
{
    return standingOn > 0;
}
// STARTER TASK 1
// void PressurePlate::collisionResponse(hitbox::GameObject*)
// {
//     // Remember that something stood on the plate, so it is not counted twice.
//     if (!alreadyPressed)
//         alreadyPressed = true;
// }
//
// void PressurePlate::onCollisionEnter(const hitbox::CollisionEvent&) {}
//
// void PressurePlate::onCollisionExit(const hitbox::CollisionEvent&) {}
//
// bool PressurePlate::isPressed() const
// {
//     return alreadyPressed;
// }
// END TASK 1

// BEGIN TASK 2: touching is not being in the gateway
bool inGateway(const hitbox::Box& gateway, const hitbox::Box& thing)
{
    // On each axis the spans must overlap: strictly less, so edges that only meet do not count.
    const bool onX =
        thing.left < gateway.left + gateway.width && gateway.left < thing.left + thing.width;
    const bool onY =
        thing.top < gateway.top + gateway.height && gateway.top < thing.top + thing.height;
    return onX && onY;
}
// STARTER TASK 2
// bool inGateway(const hitbox::Box& gateway, const hitbox::Box& thing)
// {
//     const bool acrossX =
//         thing.left <= gateway.left + gateway.width && gateway.left <= thing.left + thing.width;
//     const bool acrossY =
//         thing.top <= gateway.top + gateway.height && gateway.top <= thing.top + thing.height;
//     return acrossX && acrossY;
// }
// END TASK 2

// BEGIN TASK 3: remove every delivered crate, in the step it arrives
int removeDelivered(hitbox::World& world, std::vector<std::unique_ptr<Crate>>& crates)
{
    int removed = 0;
    // Back to front: erasing a crate moves only the ones behind it, which were already seen.
    for (std::size_t index = crates.size(); index > 0; --index)
    {
        const std::size_t at = index - 1;
        if (crates[at]->isDelivered())
        {
            world.remove(*crates[at]); // out of the World first: it only points at the crate
            crates.erase(crates.begin() + static_cast<std::ptrdiff_t>(at));
            ++removed;
        }
    }
    return removed;
}
// STARTER TASK 3
// int removeDelivered(hitbox::World& world, std::vector<std::unique_ptr<Crate>>& crates)
// {
//     int count = 0;
//     for (std::size_t index = 0; index < crates.size(); ++index)
//     {
//         if (crates[index]->isDelivered())
//         {
//             world.remove(*crates[index]); // out of the World first: it only points at it
//             crates.erase(crates.begin() + static_cast<std::ptrdiff_t>(index));
//             ++count;
//         }
//     }
//     return count;
// }
// END TASK 3
