// Actor.h - anything that walks around the top-down scene: the player, an enemy, a tree.
//
// The idea: what you SEE (the sprite) and what COLLIDES (the hitbox) are different
// boxes. The hitbox is only the feet: smaller than the sprite and at its bottom. So a head
// may overlap the wall behind it, as it would in a picture seen from above and in front,
// and the feet decide where the actor can stand and in which order things are drawn.
#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>

struct Actor
{
    sf::Vector2f feet;        // centre of the hitbox, world pixels
    sf::Vector2f hitboxSize;  // the feet box
    sf::Vector2f spriteSize;  // the picture; its bottom edge is the hitbox's bottom edge
    sf::Vector2f knockback;   // pixels per second, pushed by a hit, fades out
    float invulnerable = 0.f; // seconds left in which hits do nothing
    int health = 1;
    bool alive = true;

    sf::FloatRect hitbox() const;
    sf::FloatRect spriteBox() const;
    // The y used to sort drawing: the bottom of the feet (further down = nearer = on top).
    float depth() const;
};

// A unit vector from `from` towards `to`; straight down if the two points are the same.
sf::Vector2f directionFrom(sf::Vector2f from, sf::Vector2f to);
