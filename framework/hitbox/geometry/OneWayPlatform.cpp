// OneWayPlatform.cpp - see OneWayPlatform.h for the rule.
#include "hitbox/geometry/OneWayPlatform.h"

#include "hitbox/geometry/Range.h"

namespace hitbox
{
namespace
{
bool boxWithinRange(const Box& box)
{
    return withinExactRange(box.left) && withinExactRange(box.top) && withinExactRange(box.width) &&
           withinExactRange(box.height);
}
} // namespace

OneWayStop oneWayPlatformStop(const Box& body, Vec2 move, const Box& platform)
{
    OneWayStop result;
    result.move = move;
    if (!boxWithinRange(body) || !boxWithinRange(platform) || !withinExactRange(move))
        return result; // NaN, infinity, out of range: one defined answer, no block
    // [slide:one-way-platform]
    if (!(move.y > 0.f))
        return result; // not falling: still, or rising through it
    const Box b = normalised(body);
    const Box p = normalised(platform);
    // Double: bottom + move.y and the crossing time must not round a body that ends 1/16 px
    // below the top (far from the origin) into one that ends on it.
    const double bottom = double(b.top) + b.height;
    const double top = p.top;
    if (bottom > top)
        return result; // started below the top: passes through
    if (bottom + move.y <= top)
        return result; // ends above the top, or on it (touching)
    // When the bottom reaches the top (0 <= t < 1), does the body stand over the platform?
    const double t = (top - bottom) / move.y;
    const double left = b.left + move.x * t;
    const double right = left + b.width;
    if (!(left < double(p.left) + p.width && double(p.left) < right))
        return result; // beside it (or touching its end): falls past
    result.blocked = true;
    result.move.y = float(top - bottom);
    // [/slide]
    return result;
}

} // namespace hitbox
