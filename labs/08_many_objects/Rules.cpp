#include "Rules.h"

// BEGIN TASK 3: the two-way layer check, and the layer and mask of each kind of ball
// [slide:lab08-layers]
bool layersMayCollide(const hitbox::BroadphaseItem& a, const hitbox::BroadphaseItem& b)
{
    // Both ways: a bullet that wants to hit a ship is not enough if the ship ignores it.
    return (a.layer & b.mask) != 0 && (b.layer & a.mask) != 0;
}

CollisionFilter filterFor(BallKind kind, int owner)
{
    const std::uint32_t everything = 0xFFFFFFFF;
    const std::uint32_t myShip = owner == 0 ? layer::ship0 : layer::ship1;
    const std::uint32_t myBullets = owner == 0 ? layer::bullet0 : layer::bullet1;
    const std::uint32_t allBullets = layer::bullet0 | layer::bullet1;
    switch (kind)
    {
    case BallKind::Ship: // everything but its own bullets
        return {myShip, everything & ~myBullets};
    case BallKind::Bullet: // neither its own ship nor any bullet
        return {myBullets, everything & ~myShip & ~allBullets};
    case BallKind::Pickup: // everything but other pickups
        return {layer::pickup, everything & ~layer::pickup};
    default:
        return {layer::plain, everything};
    }
}
// [/slide]
// STARTER TASK 3
// bool layersMayCollide(const hitbox::BroadphaseItem&, const hitbox::BroadphaseItem&)
// {
//     return true; // no rules yet: every pair is worth testing
// }
//
// CollisionFilter filterFor(BallKind, int)
// {
//     return {}; // layer 1, mask "everything": every ball collides with every other
// }
// END TASK 3
