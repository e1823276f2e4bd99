#include "hitbox/geometry/SweptCircle.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Vec2.h"

#include <cmath>
#include <initializer_list>

namespace hitbox
{
namespace
{

// The largest float below 1: a time that rounds up to 1 would read as "touching at the end".
const float latestTime = std::nextafter(1.f, 0.f);

// A circle the sweeps answer for: centre and radius within the stated range (Range.h), as
// for the circle tests of Overlap.h, so a started-inside hit and its push-out always agree.
bool isUsable(const Circle& circle)
{
    return isFinite(circle) && circle.radius >= 0.f && withinExactRange(circle.center) &&
           withinExactRange(circle.radius);
}

// [slide:swept-circle-toi]
// When does a point moving from `start` by `move` first get strictly inside the circle
// (centre, radius)? |start + t * move - centre| = radius is a quadratic in t (Ericson 5.3.2):
//   a t^2 + 2 b t + c = 0,  a = move.move,  b = f.move,  c = f.f - radius^2,  f = start - centre.
// Returns a time in [0, 1), or a negative number for "no hit". The caller has already
// handled a start strictly inside (c < 0).
double entryTime(Vec2 start, Vec2 move, Vec2 centre, float radius)
{
    const double fx = double(start.x) - centre.x;
    const double fy = double(start.y) - centre.y;
    const double a = double(move.x) * move.x + double(move.y) * move.y;
    const double b = fx * move.x + fy * move.y;
    const double c = fx * fx + fy * fy - double(radius) * radius;
    if (a == 0.0 || b >= 0.0)
        return -1.0; // not moving, or moving away from (or along) the rim: never gets inside
    const double discriminant = b * b - a * c;
    if (discriminant <= 0.0)
        return -1.0; // misses, or only grazes the rim: never shares area
    // The smaller root. With b < 0 this sum has no cancellation, so it stays accurate.
    const double time = (-b - std::sqrt(discriminant)) / a;
    return time < 1.0 ? std::fmax(time, 0.0) : -1.0;
}
// [/slide]

// A cast of the point `start` by `move` against one circle, filled in as a Hit.
Hit castAgainstCircle(Vec2 start, Vec2 move, const Circle& circle)
{
    Hit hit;
    if (circle.radius == 0.f) // no area: a point never gets strictly inside (rounding in the
        return hit;           // quadratic could otherwise report a graze as a hit)
    const double time = entryTime(start, move, circle.center, circle.radius);
    if (time < 0.0)
        return hit;
    hit.hit = true;
    hit.time = std::fmin(static_cast<float>(time), latestTime);
    const Vec2 centreThen = start + move * hit.time;
    hit.normal = unitVectorOr(centreThen - circle.center, {-1.f, 0.f});
    hit.point = circle.center + hit.normal * circle.radius;
    return hit;
}

} // namespace

Hit sweepCircleVsCircle(const Circle& mover, Vec2 displacement, const Circle& target)
{
    if (!isUsable(mover) || !isUsable(target) || !withinExactRange(displacement))
        return Hit{};
    if (circleVsCircle(mover, target))
        return startedInsideHit(circleVsCircleContact(mover, target));
    // Grow the target by the mover's radius and cast the mover's centre (a point) at it.
    const Circle grown{target.center, mover.radius + target.radius};
    Hit hit = castAgainstCircle(mover.center, displacement, grown);
    if (hit.hit)
        hit.point = target.center + hit.normal * target.radius; // on the target's rim
    return hit;
}

Hit sweepCircleVsMovingCircle(const Circle& mover, Vec2 moverDisplacement, const Circle& target,
                              Vec2 targetDisplacement)
{
    // Watch from the target: it stands still and the mover makes the relative move.
    return movedWithTarget(
        sweepCircleVsCircle(mover, moverDisplacement - targetDisplacement, target),
        targetDisplacement);
}

Hit sweepCircleVsBox(const Circle& mover, Vec2 displacement, const Box& box)
{
    if (!isUsable(mover) || !isFinite(box) || !withinExactRange(displacement))
        return Hit{};
    const Box b = normalised(box);
    if (circleVsBox(mover, b))
        return startedInsideHit(circleVsBoxContact(mover, b));

    // [slide:swept-circle-box]
    // The rounded box is the union of a wide slab, a tall slab and four corner circles. The
    // centre's first entry into the union is the earliest entry into any one of them.
    const float r = mover.radius;
    const Vec2 start = mover.center;
    const Vec2 end = start + displacement;
    Hit best = segmentVsBox(start, end, {b.left - r, b.top, b.width + 2.f * r, b.height});
    const Hit tall = segmentVsBox(start, end, {b.left, b.top - r, b.width, b.height + 2.f * r});
    if (tall.hit && (!best.hit || tall.time < best.time))
        best = tall;
    for (Vec2 corner : {Vec2(b.left, b.top), Vec2(rightOf(b), b.top), Vec2(b.left, bottomOf(b)),
                        Vec2(rightOf(b), bottomOf(b))})
    {
        const Hit round = castAgainstCircle(start, displacement, Circle{corner, r});
        if (round.hit && (!best.hit || round.time < best.time)) // ties: the face wins
            best = round;
    }
    if (best.hit)
        best.point = start + displacement * best.time - best.normal * r; // on the box
    return best;
    // [/slide]
}

} // namespace hitbox
