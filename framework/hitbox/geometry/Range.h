// Range.h - the coordinates and sizes the shape tests are exact within, stated once.
//
// A float carries 24 bits: at 1e6 px its step is 1/16 px, at 1e10 it is 1024 px, so a small
// shape far away, or one 1e10 px long, is rounded by more than its own size. The polygon,
// oriented box, circle-polygon and capsule tests (Polygon.h, Capsule.h) therefore promise
// exact answers only inside a game's range and give one defined answer outside it.
#pragma once

#include "hitbox/geometry/Vec2.h"

#include <cmath>

namespace hitbox
{

// THE RANGE, in one place: every coordinate, half size and radius within +-exactRange px
// (a world of a thousand screens). Inside it the tests of Polygon.h and Capsule.h are exact
// up to float rounding: hit or miss is right whenever the true depth or gap is more than
// 1e-6 of the largest coordinate, and the depth is that close (tests/long/RangeSweepTest.cpp
// checks it at every scale; the worst seen is 2e-7). Outside it (and for NaN or infinity)
// they answer "no hit".
constexpr float exactRange = 1e6f;

// True when |value| <= exactRange (false for NaN and infinity).
[[nodiscard]] inline bool withinExactRange(float value)
{
    return std::fabs(value) <= exactRange;
}
// True when both coordinates are within the range.
[[nodiscard]] inline bool withinExactRange(Vec2 point)
{
    return withinExactRange(point.x) && withinExactRange(point.y);
}

} // namespace hitbox
