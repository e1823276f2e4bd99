// Slope.h - a slope tile: ground that rises or falls along a straight line (a ramp).
//
// A slope is the straight surface from one end to the other; everything under it, down to
// the height of its lower end, is solid (a 45-degree slope tile is the lower half of a square
// tile, cut along its diagonal). A box is not pushed out of a slope the way it is pushed out
// of a square tile (along the shallower axis: on a slope that slides it sideways). Instead one
// point, the FOOT in the middle of the box's bottom, follows the surface: the ground's height
// at the foot's x decides where the box stands, and the corners may hang over the slope.
// Sources: the Sonic Physics Guide (Sonic Retro), "Solid Tiles" and "Slope Physics": floor
// sensors under the middle of the body, and a player on the ground snapped down to a floor
// found a short way below; Rodrigo Monteiro, "The guide to implementing 2D platformers",
// Higher-Order Fun, 2012, "Type #2: Tile Based (Smooth)", slopes. y grows downward, as on
// screen, so "up" is a negative move.
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Vec2.h"

namespace hitbox
{

// A slope: its surface runs straight from `left` to `right`; under it is solid, down to the
// larger of the two ends' y. Plain data. Ends given right to left are read swapped.
struct Slope
{
    Vec2 left;
    Vec2 right;
};

// What slopeGroundAt found.
struct SlopeGround
{
    bool over = false; // x is over the slope (then y is the surface's height there)
    float y = 0.f;
};

// RULE: the height of the slope's surface at `x`, on the straight line between its ends.
// EDGES: x exactly at an end is over the slope (y: that end's y); x outside the ends is not.
// A vertical or zero-width slope (both ends at one x) is a wall, not ground: never over.
// NaN, infinity or anything outside +-exactRange (Range.h): not over.
[[nodiscard]] SlopeGround slopeGroundAt(const Slope& slope, float x);

// What standOnSlope found.
struct SlopeFoot
{
    bool grounded = false; // the foot ends on the surface: the box stands on the slope
    float moveY = 0.f;     // move the box by this (negative: up) to put the foot there
};

// RULE: the foot is the middle of the box's bottom. Over the slope, and not rising
// (velocityY >= 0), a foot below the surface is pushed up onto it, and a foot above the
// surface by at most `snapDistance` is snapped down onto it (walking down a slope stays on
// it instead of falling off it in little hops); either way the box is grounded.
// A rising box (velocityY < 0, a jump) is never moved and never grounded: the jump leaves
// the slope. EDGES: a foot exactly on the surface is grounded with moveY 0 (touching is
// standing); a foot deeper than the slope's lowest end is under the slope, not on it
// (nothing); the foot's x at an end counts; not over the slope (slopeGroundAt): nothing.
// snapDistance <= 0 or NaN: no snapping down (only a foot on or below the surface). Negative
// box sizes are read as normalised(); NaN, infinity or anything outside +-exactRange: nothing.
[[nodiscard]] SlopeFoot standOnSlope(const Box& box, float velocityY, const Slope& slope,
                                     float snapDistance);

} // namespace hitbox
