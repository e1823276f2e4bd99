// Actor.h - anything that walks around the top-down scene: the player, an enemy, a tree.
//
// The idea: what you SEE (the sprite) and what COLLIDES (the hitbox) are different
// boxes. The hitbox is only the feet: smaller than the sprite and at its bottom. So a head
// may overlap the wall behind it, as it would in a picture seen from above and in front,
// and the feet decide where the actor can stand and in which order things are drawn.
#pragma once

#include "hitbox/geometry/Shapes.h"

struct Actor
{
    hitbox::Vec2 feet;        // centre of the hitbox, world pixels
    hitbox::Vec2 hitboxSize;  // the feet box
    hitbox::Vec2 spriteSize;  // the picture; its bottom edge is the hitbox's bottom edge
    hitbox::Vec2 knockback;   // pixels per second, pushed by a hit, fades out
    float invulnerable = 0.f; // seconds left in which hits do nothing
    int health = 1;
    bool alive = true;

    hitbox::Box hitbox() const;
    hitbox::Box spriteBox() const;
    // The y used to sort drawing: the bottom of the feet (further down = nearer = on top).
    float depth() const;
};

// A unit vector from `from` towards `to`; straight down if the two points are the same.
hitbox::Vec2 directionFrom(hitbox::Vec2 from, hitbox::Vec2 to);
