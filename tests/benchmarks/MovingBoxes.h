// MovingBoxes.h - the benchmark's workload: N boxes drifting and bouncing in a square world.
//
// Sides between 0.5 and 2 units (x4), speeds up to 2 units per second at 60 frames per
// second, and a world whose area grows with N so every box overlaps about three others at
// any N (the density stays the same, so a method whose cost per box stays flat scales).
// Units are Box2D's metres: the size range Box2D is tuned for, so its tree is at its best.
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <vector>

struct MovingBoxes
{
    MovingBoxes(std::size_t count, unsigned seed);
    // One frame: every box moves, bouncing off the world's edges; `items` gets the new boxes.
    void step();

    float worldSide = 0.f;
    std::vector<float> x, y, width, height, velocityX, velocityY;
    std::vector<hitbox::Vec2> lastMove; // the displacement of the last step, for Box2D
    std::vector<hitbox::BroadphaseItem> items;
};
