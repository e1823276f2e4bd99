#include "hitbox/geometry/Sweep.h"

#include "hitbox/geometry/Range.h"

#include "hitbox/geometry/Overlap.h"

#include <cmath>
#include <limits>

namespace hitbox
{
namespace
{

constexpr float infinity = std::numeric_limits<float>::infinity();

// The stretch of the step (as fractions of the move) during which two intervals on one axis
// share some length. `enter >= exit` means never.
struct TimeSpan
{
    float enter;
    float exit;
};

// [slide:slab]
// One slab of the slab method. The mover's interval [moverMin, moverMax] moves by `move`
// over the step; the target's interval stays put. Growing the target by the mover's size
// (the Minkowski sum, as javidx9 does) and casting the mover's centre gives the same times; we
// subtract the original edges instead, so that boxes that touch give exactly 0 and no
// rounding from halving a width can turn "touching" into "overlapping".
TimeSpan overlapTimes(float moverMin, float moverMax, float targetMin, float targetMax, float move)
{
    if (move == 0.f)
    {
        // Not moving on this axis: it overlaps for the whole step or never. Dividing would
        // give 0 / 0 = NaN when an edge lies exactly on the line (the divide-by-zero case in
        // javidx9's video).
        const bool overlapping = spansOverlap(moverMin, moverMax, targetMin, targetMax);
        return overlapping ? TimeSpan{-infinity, infinity} : TimeSpan{infinity, -infinity};
    }
    // Enter when the leading edge reaches the target's near edge; leave when the trailing
    // edge passes its far edge.
    if (move > 0.f)
        return {(targetMin - moverMax) / move, (targetMax - moverMin) / move};
    return {(targetMax - moverMin) / move, (targetMin - moverMax) / move};
}
// [/slide]

} // namespace

Hit startedInsideHit(const Contact& overlap)
{
    Hit hit;
    hit.hit = true;
    hit.startedInside = true;
    hit.time = 0.f;
    hit.normal = overlap.normal;
    hit.depth = overlap.depth;
    hit.point = overlap.point;
    return hit;
}

// [slide:swept-box]
Hit sweepBoxVsBox(const Box& moverBox, Vec2 displacement, const Box& targetBox)
{
    Hit hit;
    if (!isFinite(moverBox) || !isFinite(displacement) || !isFinite(targetBox))
        return hit;
    const Box mover = normalised(moverBox);
    const Box target = normalised(targetBox);
    if (boxVsBox(mover, target))
        return startedInsideHit(boxVsBoxContact(mover, target));

    const TimeSpan x =
        overlapTimes(mover.left, rightOf(mover), target.left, rightOf(target), displacement.x);
    const TimeSpan y =
        overlapTimes(mover.top, bottomOf(mover), target.top, bottomOf(target), displacement.y);

    // They share area only while they overlap on BOTH axes: from the later entry to the
    // earlier exit. That stretch must be non-empty and fall inside this step.
    const float enter = std::fmax(x.enter, y.enter);
    const float exit = std::fmin(x.exit, y.exit);
    if (!(enter < exit && enter < 1.f && exit > 0.f))
        return hit;

    hit.hit = true;
    // enter can be -0 when starting exactly touching.
    hit.time = enter > 0.f ? enter : 0.f;

    // The axis entered last is the face that was hit. An exact corner enters both at once:
    // the x axis wins, so the normal is never (0, 0).
    const Vec2 moved(mover.left + displacement.x * hit.time, mover.top + displacement.y * hit.time);
    if (x.enter >= y.enter)
    {
        const bool fromLeft = displacement.x > 0.f;
        hit.normal = {fromLeft ? -1.f : 1.f, 0.f};
        const float sharedTop = std::fmax(moved.y, target.top);
        const float sharedBottom = std::fmin(moved.y + mover.height, bottomOf(target));
        hit.point = {fromLeft ? target.left : rightOf(target), (sharedTop + sharedBottom) / 2.f};
    }
    else
    {
        const bool fromAbove = displacement.y > 0.f;
        hit.normal = {0.f, fromAbove ? -1.f : 1.f};
        const float sharedLeft = std::fmax(moved.x, target.left);
        const float sharedRight = std::fmin(moved.x + mover.width, rightOf(target));
        hit.point = {(sharedLeft + sharedRight) / 2.f, fromAbove ? target.top : bottomOf(target)};
    }
    return hit;
}
// [/slide]

Hit segmentVsBox(Vec2 start, Vec2 end, const Box& box)
{
    // Outside the exact range (Range.h) the move end - start can overflow to infinity (from
    // -3e38 to 3e38) and the hit time is meaningless: "no hit", as Sweep.h states.
    if (!withinExactRange(start) || !withinExactRange(end))
        return Hit{};
    // A point is a box of zero size, so the segment is that box's move.
    return sweepBoxVsBox(Box(start, Vec2(0.f, 0.f)), end - start, box);
}

Hit sweepBoxVsMovingBox(const Box& mover, Vec2 moverDisplacement, const Box& target,
                        Vec2 targetDisplacement)
{
    // Watch from the target: it stands still and the mover makes the relative move.
    return movedWithTarget(sweepBoxVsBox(mover, moverDisplacement - targetDisplacement, target),
                           targetDisplacement);
}

Hit movedWithTarget(Hit hitSeenFromTarget, Vec2 targetDisplacement)
{
    if (hitSeenFromTarget.hit)
        hitSeenFromTarget.point += targetDisplacement * hitSeenFromTarget.time;
    return hitSeenFromTarget;
}

} // namespace hitbox
