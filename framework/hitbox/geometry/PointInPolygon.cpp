#include "hitbox/geometry/PointInPolygon.h"

#include "hitbox/geometry/Range.h"

#include <cstddef>

namespace hitbox
{

namespace
{
// The products of two float differences are worked in double: a float product is exact
// there, so "exactly on the edge" (cross product 0) is decided without float rounding.
double crossOf(Vec2 a, Vec2 b, Vec2 point)
{
    const double abx = static_cast<double>(b.x) - a.x;
    const double aby = static_cast<double>(b.y) - a.y;
    const double apx = static_cast<double>(point.x) - a.x;
    const double apy = static_cast<double>(point.y) - a.y;
    return abx * apy - aby * apx;
}

bool onSegment(Vec2 a, Vec2 b, Vec2 point)
{
    if (crossOf(a, b, point) != 0.0)
        return false;
    const bool withinX = (point.x >= a.x && point.x <= b.x) || (point.x >= b.x && point.x <= a.x);
    const bool withinY = (point.y >= a.y && point.y <= b.y) || (point.y >= b.y && point.y <= a.y);
    return withinX && withinY;
}
} // namespace

PointInPolygonResult pointInPolygon(const Polygon& polygon, Vec2 point)
{
    PointInPolygonResult result;
    if (!withinExactRange(point))
        return result;
    for (const Vec2 corner : polygon.points)
    {
        if (!withinExactRange(corner))
            return result;
    }
    const std::size_t count = polygon.points.size();
    for (std::size_t index = 0; index < count; ++index)
    {
        const Vec2 a = polygon.points[index];
        const Vec2 b = polygon.points[(index + 1) % count];
        if (onSegment(a, b, point))
        {
            result.onEdge = true;
            result.crossings = 0;
            return result;
        }
        // Half-open rule: the edge counts when exactly one end is strictly below the point's
        // line (y greater, screen y down), so a corner on the ray is counted once or not at all.
        if ((a.y > point.y) == (b.y > point.y))
            continue;
        // Where the edge crosses the ray's line, compared with the point: the sign of the
        // cross product, oriented so that the edge runs downwards (a above b).
        const double side = (a.y < b.y) ? crossOf(a, b, point) : crossOf(b, a, point);
        // side > 0: the point is left of the downward edge in screen coordinates, so the
        // ray to +x meets it.
        if (side > 0.0)
            ++result.crossings;
    }
    // A polygon with no area (all corners on one line) is crossed an even number of times
    // (out and back along the same line), so it is never inside without a special case.
    result.inside = result.crossings % 2 == 1;
    return result;
}

} // namespace hitbox
