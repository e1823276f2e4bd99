#include "hitbox/geometry/RayCircle.h"

#include "hitbox/geometry/Range.h"

#include <cmath>

namespace hitbox
{

// [slide:ray-circle]
RayCircleResult segmentVsCircle(Vec2 start, Vec2 end, const Circle& circle)
{
    RayCircleResult result;
    if (!withinExactRange(start) || !withinExactRange(end) || !withinExactRange(circle.center) ||
        !withinExactRange(circle.radius) || !(circle.radius > 0.f))
        return result;
    // |f + t d| = r with f = start - centre:  a t^2 + 2 b t + c = 0.
    const double fx = double(start.x) - circle.center.x;
    const double fy = double(start.y) - circle.center.y;
    const double dx = double(end.x) - start.x;
    const double dy = double(end.y) - start.y;
    const double a = dx * dx + dy * dy;
    const double b = fx * dx + fy * dy;
    const double c = fx * fx + fy * fy - double(circle.radius) * circle.radius;
    if (c < 0.0) // strictly inside already
    {
        result.hit = result.startedInside = true;
        result.nearTime = 0.f;
        result.farTime = a > 0.0 ? float((-b + std::sqrt(b * b - a * c)) / a) : 0.f;
        result.point = start;
        return result;
    }
    const double discriminant = b * b - a * c;
    if (a == 0.0 || b >= 0.0 || discriminant <= 0.0)
        return result; // not moving, heading away (or along the rim), missing or grazing
    const double root = std::sqrt(discriminant);
    const double nearTime = (-b - root) / a; // b < 0: no cancellation
    if (nearTime >= 1.0)
        return result; // reaches the rim at its end or beyond: touching is not colliding
    result.hit = true;
    // A time just below 1 must not round up to 1 (that would read as "touching at the end").
    result.nearTime = std::fmin(float(std::fmax(nearTime, 0.0)), std::nextafter(1.f, 0.f));
    result.farTime = float((-b + root) / a);
    result.point = start + (end - start) * result.nearTime;
    // From the exact entry point in double, so a far circle still gets a unit normal.
    const Vec2 outwards{float(fx + nearTime * dx), float(fy + nearTime * dy)};
    result.normal = unitVectorOr(outwards, {-1.f, 0.f});
    return result;
}
// [/slide]

} // namespace hitbox
