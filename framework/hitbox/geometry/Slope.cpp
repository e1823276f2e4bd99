// Slope.cpp - see Slope.h for the rules.
#include "hitbox/geometry/Slope.h"

#include "hitbox/geometry/Range.h"

#include <algorithm>

namespace hitbox
{

SlopeGround slopeGroundAt(const Slope& slope, float x)
{
    SlopeGround ground;
    if (!withinExactRange(slope.left) || !withinExactRange(slope.right) || !withinExactRange(x))
        return ground;
    const bool swapped = slope.right.x < slope.left.x;
    const Vec2 a = swapped ? slope.right : slope.left;
    const Vec2 b = swapped ? slope.left : slope.right;
    if (!(a.x < b.x) || x < a.x || x > b.x)
        return ground; // a wall (no width), or beside the slope
    // Double: the fraction along must not round a foot at an end off the slope's height.
    const double along = (double(x) - a.x) / (double(b.x) - a.x);
    ground.over = true;
    ground.y = float(a.y + (double(b.y) - a.y) * along);
    return ground;
}

SlopeFoot standOnSlope(const Box& box, float velocityY, const Slope& slope, float snapDistance)
{
    SlopeFoot foot;
    if (!withinExactRange(box.left) || !withinExactRange(box.top) || !withinExactRange(box.width) ||
        !withinExactRange(box.height) || !withinExactRange(velocityY))
        return foot;
    // [slide:slope-foot]
    if (velocityY < 0.f)
        return foot; // rising: a jump leaves the slope
    const Box b = normalised(box);
    const float footX = b.left + b.width / 2.f;
    const float footY = b.top + b.height;
    const SlopeGround ground = slopeGroundAt(slope, footX);
    if (!ground.over || footY > std::max(slope.left.y, slope.right.y))
        return foot; // beside the slope, or under it
    // How far the foot is above the surface (negative: inside the slope).
    const float above = ground.y - footY;
    if (above > 0.f && !(above <= snapDistance))
        return foot; // too high to pull down (or no pulling): in the air
    foot.grounded = true;
    foot.moveY = above; // down onto the surface, or up out of the slope
    // [/slide]
    return foot;
}

} // namespace hitbox
