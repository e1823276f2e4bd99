#include "hitbox/geometry/Capsule.h"

#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/SupportWalk.h"
#include "hitbox/geometry/Vec2.h"

#include <algorithm>
#include <cmath>

namespace hitbox
{
namespace
{

bool isUsable(const Capsule& capsule)
{
    return withinExactRange(capsule.start) && withinExactRange(capsule.end) &&
           withinExactRange(capsule.radius) && capsule.radius >= 0.f;
}

double clamp01(double value)
{
    return std::min(1.0, std::max(0.0, value));
}

Vec2 middleOf(const Capsule& capsule)
{
    return (capsule.start + capsule.end) / 2.f;
}

// A unit vector at right angles to the segment, on the side of `towards` (or (-y, x) when
// `towards` is on the line). The zero vector when the segment has no length.
Vec2 sideNormal(Vec2 start, Vec2 end, Vec2 towards)
{
    Vec2 normal = unitVectorOr(perpendicular(end - start), {0.f, 0.f});
    if (dot(towards - start, normal) < 0.f)
        normal = -normal;
    return normal;
}

// The capsules' cores touch or cross: push A across B's segment (or across A's own segment
// when B's is a point) far enough that A's whole segment is radiusSum away from that line.
Contact crossingContact(const Capsule& a, const Capsule& b, Vec2 pointOnB)
{
    Contact contact;
    contact.hit = true;
    const float radiusSum = a.radius + b.radius;
    Vec2 normal = sideNormal(b.start, b.end, middleOf(a));
    if (normal != Vec2())
    {
        const float deepestEnd =
            std::fmin(dot(a.start - b.start, normal), dot(a.end - b.start, normal));
        contact.normal = normal;
        contact.depth = radiusSum - std::fmin(deepestEnd, 0.f);
    }
    else
    {
        // B is a point lying on A's segment: move A sideways off it.
        normal = unitVectorOr(perpendicular(a.end - a.start), {-1.f, 0.f});
        contact.normal = normal;
        contact.depth = radiusSum;
    }
    contact.point = pointOnB + contact.normal * b.radius;
    return contact;
}

// Which side of the line a->b the point p is on (double, so the sign is trustworthy).
double sideOf(Vec2 a, Vec2 b, Vec2 p)
{
    return (double(b.x) - a.x) * (double(p.y) - a.y) - (double(b.y) - a.y) * (double(p.x) - a.x);
}

bool segmentsCross(Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1)
{
    const double first = sideOf(a0, a1, b0) * sideOf(a0, a1, b1);
    const double second = sideOf(b0, b1, a0) * sideOf(b0, b1, a1);
    return first < 0.0 && second < 0.0;
}

// Closest points this near are "the same point" for choosing a direction: the rounding of
// the closest-point formula is about a millionth of the coordinates' size.
bool nearlySame(Vec2 a, Vec2 b)
{
    const float scale = 1.f + std::fmax(std::fmax(std::fabs(a.x), std::fabs(a.y)),
                                        std::fmax(std::fabs(b.x), std::fabs(b.y)));
    return length(a - b) <= 1e-6f * scale;
}

} // namespace

// [slide:capsule-closest-point]
Vec2 closestPointOnSegment(Vec2 point, Vec2 start, Vec2 end)
{
    const Vec2 along = end - start;
    const double lengthSquared = double(along.x) * along.x + double(along.y) * along.y;
    if (lengthSquared == 0.0)
        return start; // a segment with no length is a point
    // How far along the segment the point's shadow falls (0 = start, 1 = end), kept on it.
    const double t =
        (double(point.x - start.x) * along.x + double(point.y - start.y) * along.y) / lengthSquared;
    const double kept = clamp01(t);
    return {static_cast<float>(start.x + along.x * kept),
            static_cast<float>(start.y + along.y * kept)};
}

Contact capsuleVsCircle(const Capsule& capsule, const Circle& circle)
{
    // A circle is a capsule whose segment has no length. The capsule test finds the nearest
    // point of each core (closestPointOnSegment, for a point) and treats them as two circles.
    return capsuleVsCapsule(capsule, Capsule{circle.center, circle.center, circle.radius});
}
// [/slide]

namespace
{

// How far along each segment (0..1) the closest pair lies.
struct SegmentTimes
{
    double s;
    double t;
};

SegmentTimes closestTimes(Vec2 start1, Vec2 end1, Vec2 start2, Vec2 end2)
{
    // Write the points as start1 + s * d1 and start2 + t * d2 and minimise the distance over
    // s and t in [0, 1]: set both derivatives to zero, then clamp (Ericson, Real-Time Collision
    // Detection, 5.1.9, whose letters are a = length1Squared, e = length2Squared,
    // b = directionsDot, c = offsetAlong1, f = offsetAlong2 and r = offset).
    const Vec2 d1 = end1 - start1;
    const Vec2 d2 = end2 - start2;
    const Vec2 offset = start1 - start2;
    const double length1Squared = double(d1.x) * d1.x + double(d1.y) * d1.y;
    const double length2Squared = double(d2.x) * d2.x + double(d2.y) * d2.y;
    const double offsetAlong2 = double(d2.x) * offset.x + double(d2.y) * offset.y;
    double s = 0.0;
    double t = 0.0;
    if (length1Squared == 0.0 && length2Squared == 0.0)
        return {0.0, 0.0}; // two points
    if (length1Squared == 0.0)
    {
        t = clamp01(offsetAlong2 / length2Squared); // the first is a point
    }
    else
    {
        const double offsetAlong1 = double(d1.x) * offset.x + double(d1.y) * offset.y;
        if (length2Squared == 0.0)
        {
            s = clamp01(-offsetAlong1 / length1Squared); // the second is a point
        }
        else
        {
            const double directionsDot = double(d1.x) * d2.x + double(d1.y) * d2.y;
            const double denominator =
                length1Squared * length2Squared - directionsDot * directionsDot; // 0 when parallel
            s = denominator > 0.0
                    ? clamp01((directionsDot * offsetAlong2 - offsetAlong1 * length2Squared) /
                              denominator)
                    : 0.0;
            t = (directionsDot * s + offsetAlong2) / length2Squared;
            // t off the second segment: clamp it and find s again for that t.
            if (t < 0.0)
            {
                t = 0.0;
                s = clamp01(-offsetAlong1 / length1Squared);
            }
            else if (t > 1.0)
            {
                t = 1.0;
                s = clamp01((directionsDot - offsetAlong1) / length1Squared);
            }
        }
    }
    return {s, t};
}

// The point at `time` along start..end, in double precision.
void pointAt(Vec2 start, Vec2 end, double time, double& x, double& y)
{
    x = start.x + (double(end.x) - start.x) * time;
    y = start.y + (double(end.y) - start.y) * time;
}

} // namespace

SegmentPoints closestPointsOfSegments(Vec2 start1, Vec2 end1, Vec2 start2, Vec2 end2)
{
    const SegmentTimes times = closestTimes(start1, end1, start2, end2);
    double x1, y1, x2, y2;
    pointAt(start1, end1, times.s, x1, y1);
    pointAt(start2, end2, times.t, x2, y2);
    return {{static_cast<float>(x1), static_cast<float>(y1)},
            {static_cast<float>(x2), static_cast<float>(y2)}};
}

Contact capsuleVsCapsule(const Capsule& a, const Capsule& b)
{
    if (!isUsable(a) || !isUsable(b))
        return Contact{};
    const SegmentPoints closest = closestPointsOfSegments(a.start, a.end, b.start, b.end);
    const float radiusSum = a.radius + b.radius;
    const bool crossing = segmentsCross(a.start, a.end, b.start, b.end);
    if (crossing || nearlySame(closest.first, closest.second))
    {
        const float depthAtClosest = radiusSum - length(closest.first - closest.second);
        if (!penetrates(depthAtClosest) && !(crossing && penetrates(radiusSum)))
            return Contact{}; // two segments with no area, or apart by the radii or more
        return crossingContact(a, b, closest.second);
    }
    // Otherwise it is two circles, one at each closest point. The direction between them is
    // worked out in double: when the cores nearly touch, float rounding would tilt it.
    const SegmentTimes times = closestTimes(a.start, a.end, b.start, b.end);
    double ax, ay, bx, by;
    pointAt(a.start, a.end, times.s, ax, ay);
    pointAt(b.start, b.end, times.t, bx, by);
    const double distance = std::hypot(ax - bx, ay - by);
    Contact contact;
    contact.depth = static_cast<float>(radiusSum - distance);
    if (!penetrates(contact.depth))
        return Contact{};
    contact.hit = true;
    contact.normal = {static_cast<float>((ax - bx) / distance),
                      static_cast<float>((ay - by) / distance)};
    contact.point =
        Vec2(static_cast<float>(bx), static_cast<float>(by)) + contact.normal * b.radius;
    return contact;
}

Contact capsuleVsPolygon(const Capsule& capsule, const Polygon& polygon)
{
    Contact contact;
    const std::vector<Vec2> corners = convexHull(polygon).points; // empty when out of range
    if (!isUsable(capsule) || corners.empty())
        return contact;
    if (capsule.radius == 0.f && corners.size() < 3)
        return contact; // a segment against a polygon with no area: nothing to share

    // Candidate axes (see the header): the polygon's edge normals, the capsule's normal, and
    // from each capsule end to the corner nearest it (where the round end meets a corner).
    std::vector<Vec2> axes;
    std::vector<bool> fromPolygonFace;
    for (std::size_t i = 0; i < corners.size(); ++i)
    {
        axes.push_back(perpendicular(corners[(i + 1) % corners.size()] - corners[i]));
        fromPolygonFace.push_back(true);
    }
    axes.push_back(perpendicular(capsule.end - capsule.start));
    fromPolygonFace.push_back(false);
    for (Vec2 end : {capsule.start, capsule.end})
    {
        Vec2 nearest = corners[0];
        for (Vec2 corner : corners)
            if (dot(corner - end, corner - end) < dot(nearest - end, nearest - end))
                nearest = corner;
        axes.push_back(nearest - end);
        fromPolygonFace.push_back(false);
    }

    // The edge normals come in order round the polygon: walking support points (SupportWalk.h)
    // find its shadow on each in O(1) steps on average, so the whole test is O(n).
    SupportWalk furthest{corners}, nearest{corners};
    bool found = false;
    bool bestFromFace = false;
    for (std::size_t i = 0; i < axes.size(); ++i)
    {
        Vec2 axis = unitVectorOr(axes[i], {0.f, 0.f});
        if (axis == Vec2())
            continue; // a repeated corner, or a capsule end on a corner
        if (axis.x < 0.f || (axis.x == 0.f && axis.y < 0.f))
            axis = -axis; // point right (or down): ties then go left (or up)
        const float polygonMin = static_cast<float>(-nearest.furthestAlong(-axis));
        const float polygonMax = static_cast<float>(furthest.furthestAlong(axis));
        const float capsuleMin =
            std::fmin(dot(capsule.start, axis), dot(capsule.end, axis)) - capsule.radius;
        const float capsuleMax =
            std::fmax(dot(capsule.start, axis), dot(capsule.end, axis)) + capsule.radius;
        const float pushPositive = polygonMax - capsuleMin;
        const float pushNegative = capsuleMax - polygonMin;
        const float overlap = std::fmin(pushPositive, pushNegative);
        if (!penetrates(overlap))
            return Contact{}; // a separating axis: apart (touching counts as apart)
        if (!found || overlap < contact.depth)
        {
            found = true;
            contact.depth = overlap;
            contact.normal = pushNegative <= pushPositive ? -axis : axis;
            bestFromFace = fromPolygonFace[i];
        }
    }
    contact.hit = true;
    if (!found)
    {
        // No axis at all: the capsule is a point sitting exactly on a one-point polygon
        // (radius > 0 here). Push towards -x, as circleVsCircleContact does.
        contact.normal = {-1.f, 0.f};
        contact.depth = capsule.radius;
        contact.point = corners[0];
        return contact;
    }
    const Vec2 n = contact.normal;
    if (bestFromFace)
    {
        // The capsule's deepest point, moved onto the polygon's face.
        const Vec2 deepestEnd =
            dot(capsule.start, n) <= dot(capsule.end, n) ? capsule.start : capsule.end;
        contact.point = deepestEnd - n * capsule.radius + n * contact.depth;
    }
    else
    {
        // The polygon's corner that reaches deepest into the capsule.
        contact.point = corners[0];
        for (Vec2 corner : corners)
            if (dot(corner, n) > dot(contact.point, n))
                contact.point = corner;
    }
    return contact;
}

} // namespace hitbox
