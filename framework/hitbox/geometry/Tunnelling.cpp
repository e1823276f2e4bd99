#include "hitbox/geometry/Tunnelling.h"

#include "hitbox/geometry/Capsule.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/geometry/SweptCircle.h"
#include "hitbox/geometry/Vec2.h"

#include <cmath>

namespace hitbox
{
namespace
{

Box movedBy(Box box, Vec2 offset)
{
    box.left += offset.x;
    box.top += offset.y;
    return box;
}

bool isUsable(const Circle& circle)
{
    return isFinite(circle) && circle.radius >= 0.f;
}

Box boundsOf(const Circle& circle)
{
    return {circle.center.x - circle.radius, circle.center.y - circle.radius, 2.f * circle.radius,
            2.f * circle.radius};
}

} // namespace

// [slide:tunnelling-check]
bool canTunnel(const Box& moverBox, Vec2 displacement, const Box& targetBox)
{
    if (!isFinite(moverBox) || !isFinite(displacement) || !isFinite(targetBox))
        return false;
    const Box mover = normalised(moverBox);
    const Box target = normalised(targetBox);
    // To get from touching one side to touching the other, the mover travels its own size
    // plus the target's. A step at least that long can jump the target completely.
    const bool longEnough = std::fabs(displacement.x) >= mover.width + target.width ||
                            std::fabs(displacement.y) >= mover.height + target.height;
    // Broad phase: the target must lie where this step could take the mover.
    return longEnough && boxVsBox(sweptBounds(mover, displacement), target);
}
// [/slide]

bool canTunnel(const Circle& mover, Vec2 displacement, const Circle& target)
{
    if (!isUsable(mover) || !isUsable(target) || !isFinite(displacement))
        return false;
    const bool longEnough = length(displacement) >= 2.f * (mover.radius + target.radius);
    // The mover's path is a capsule: does it reach the target at all?
    const Capsule path{mover.center, mover.center + displacement, mover.radius};
    return longEnough && capsuleVsCircle(path, target).hit;
}

bool canTunnel(const Circle& mover, Vec2 displacement, const Box& target)
{
    if (!isUsable(mover))
        return false;
    return canTunnel(boundsOf(mover), displacement, target);
}

bool discreteTestMisses(const Box& mover, Vec2 displacement, const Box& target)
{
    return sweepBoxVsBox(mover, displacement, target).hit && !boxVsBox(mover, target) &&
           !boxVsBox(movedBy(mover, displacement), target);
}

bool discreteTestMisses(const Circle& mover, Vec2 displacement, const Circle& target)
{
    const Circle moved{mover.center + displacement, mover.radius};
    return sweepCircleVsCircle(mover, displacement, target).hit && !circleVsCircle(mover, target) &&
           !circleVsCircle(moved, target);
}

Box sweptBounds(const Box& box, Vec2 displacement)
{
    const Box start = normalised(box);
    const Box end = movedBy(start, displacement);
    const float left = std::fmin(start.left, end.left);
    const float top = std::fmin(start.top, end.top);
    const float right = std::fmax(rightOf(start), rightOf(end));
    const float bottom = std::fmax(bottomOf(start), bottomOf(end));
    return {left, top, right - left, bottom - top};
}

Box sweptBounds(const Circle& circle, Vec2 displacement)
{
    return sweptBounds(boundsOf(circle), displacement);
}

Vec2 speculativeVelocity(const Box& mover, Vec2 velocity, float dt, const std::vector<Box>& solids)
{
    if (!isFinite(velocity) || !std::isfinite(dt) || !(dt > 0.f))
        return velocity;
    // Speculative contacts (Katy Coe, "2D Platform Games Part 1"): rather than resolve an overlap
    // afterwards, shorten the move so it never happens. The earliest time of impact over all solids
    // decides how much of it to keep.
    float earliest = 1.f;
    for (const Box& solid : solids)
    {
        const Hit hit = sweepBoxVsBox(mover, velocity * dt, solid);
        if (hit.hit && !hit.startedInside)
            earliest = std::fmin(earliest, hit.time);
    }
    // Moving to exactly the time of impact can round to a hair inside the solid. That must
    // not happen: next step the box would count as "already inside", keep its full velocity
    // and pass through. So if it does, halve the interval between time 0 (not inside) and
    // that time until the latest time that leaves the box outside every solid it was not
    // already overlapping is found, to the last bit of the float.
    auto endsInsideASolid = [&](float time)
    {
        const Box moved = movedBy(mover, velocity * time * dt);
        for (const Box& solid : solids)
            if (boxVsBox(moved, solid) && !boxVsBox(mover, solid))
                return true;
        return false;
    };
    if (endsInsideASolid(earliest))
    {
        float outside = 0.f, inside = earliest;
        for (float middle = inside / 2.f; middle > outside && middle < inside;
             middle = outside + (inside - outside) / 2.f)
        {
            if (endsInsideASolid(middle))
                inside = middle;
            else
                outside = middle;
        }
        earliest = outside;
    }
    return velocity * earliest;
}

} // namespace hitbox
