// OneWayPlatform.h - a platform you can jump up through and land on (a "jump-through" or
// "cloud" platform in Mario and most platformers).
//
// A one-way platform is solid only from above: the question is not "do the boxes overlap" but
// "was the body above the platform when this step began, and is it falling". The rule looks at
// where the body was at the start of the step, so a body that jumped half-way through from
// below keeps rising (or falls back down) through it instead of being snapped on top.
// (Rodrigo Monteiro, "The guide to implementing 2D platformers", Higher-Order Fun, 2012,
// "Type #2: Tile Based (Smooth)", one-way platforms.) y grows downward, as on screen.
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

// What oneWayPlatformStop found.
struct OneWayStop
{
    bool blocked = false; // the platform stopped the body this step
    Vec2 move;            // the move to make: the asked move, or with y cut so the body's
                          // bottom ends on the platform's top (then it touches, not overlaps)
};

// RULE: a one-way platform blocks only a body moving down (move.y > 0) whose bottom was at or
// above the platform's top at the start of the step (bottom <= top: touching counts as above,
// so a body standing on it is held) and whose bottom would end strictly below that top.
// EDGES: ending exactly on the top is no block (touching is not colliding); horizontally the
// body must overlap the platform's span with some length when its bottom reaches the top (a
// body whose side only touches the platform's end falls past it); move.y <= 0 (zero velocity,
// moving up through it) never blocks; a body starting below the top falls on through. Negative
// sizes are read as normalised(); NaN, infinity or anything outside +-exactRange (Range.h): no
// block, the move unchanged.
[[nodiscard]] OneWayStop oneWayPlatformStop(const Box& body, Vec2 move, const Box& platform);

} // namespace hitbox
