#include "hitbox/geometry/Polygon.h"

#include "hitbox/geometry/Capsule.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Vec2.h"

#include <cmath>

namespace hitbox
{
namespace
{

// The polygon without NaN (then empty) and without repeated neighbouring points, so every
// edge has a length and a direction.
std::vector<Vec2> cleaned(const Polygon& polygon)
{
    std::vector<Vec2> points;
    for (Vec2 point : polygon.points)
    {
        if (!isFinite(point))
            return {};
        if (points.empty() || point != points.back())
            points.push_back(point);
    }
    while (points.size() > 1 && points.front() == points.back())
        points.pop_back();
    return points;
}

float twiceSignedAreaOf(const std::vector<Vec2>& points)
{
    float sum = 0.f;
    for (std::size_t i = 0; i < points.size(); ++i)
        sum += cross(points[i], points[(i + 1) % points.size()]);
    return sum;
}

// The shadow of a polygon on an axis (not necessarily of unit length).
struct Shadow
{
    float min;
    float max;
};

Shadow shadowOn(const std::vector<Vec2>& points, Vec2 axis)
{
    Shadow shadow{dot(points[0], axis), dot(points[0], axis)};
    for (Vec2 point : points)
    {
        const float along = dot(point, axis);
        shadow.min = std::fmin(shadow.min, along);
        shadow.max = std::fmax(shadow.max, along);
    }
    return shadow;
}

// One edge's axis, turned to point right (or down when vertical) so that "ties go to the
// negative direction" means left or up, as in boxVsBoxContact. Not unit length: with whole
// number coordinates the shadows are then exact, so touching is found exactly.
Vec2 edgeAxis(Vec2 from, Vec2 to)
{
    Vec2 axis = perpendicular(to - from);
    if (axis.x < 0.f || (axis.x == 0.f && axis.y < 0.f))
        axis = -axis;
    return axis;
}

// [slide:sat-axis-test]
// One axis of the separating axis theorem: cast both shadows on the axis. Their overlap is
// how far A must move along the axis to get clear of B; overlap <= 0 (a gap, or shadows
// that only touch) means this axis separates the shapes.
struct AxisOverlap
{
    bool apart;
    float overlap; // pixels; minus the gap when apart
    Vec2 towardsA; // unit: the way to move A (from B's side to A's side)
};

AxisOverlap overlapOnAxis(const std::vector<Vec2>& a, const std::vector<Vec2>& b, Vec2 axis)
{
    const Shadow shadowA = shadowOn(a, axis);
    const Shadow shadowB = shadowOn(b, axis);
    const float pushPositive = shadowB.max - shadowA.min; // move A along +axis to clear B
    const float pushNegative = shadowA.max - shadowB.min; // or along -axis
    // Equal pushes go the negative way (left or up), as boxVsBoxContact does.
    const bool negative = pushNegative <= pushPositive;
    const float push = negative ? pushNegative : pushPositive;
    const Vec2 unit = axis / length(axis);
    // (+ 0.f turns a -0 into 0, so an axis-aligned normal prints and compares cleanly.)
    const Vec2 towardsA = negative ? Vec2(-unit.x + 0.f, -unit.y + 0.f) : unit;
    return {push <= 0.f, push / length(axis), towardsA};
}
// [/slide]

// The best axes found so far by the search.
struct Search
{
    bool anyAxis = false;
    bool separated = false;
    float largestGap = 0.f;   // pixels, while separated
    Vec2 gapAxis;             // unit, from B's side towards A's side
    float leastOverlap = 0.f; // pixels, while not separated
    Vec2 overlapAxis;         // unit, out of B towards A: the contact normal
    bool overlapAxisIsAnEdgeOfB = false;
};

void tryEdgesOf(const std::vector<Vec2>& owner, bool ownerIsB, const std::vector<Vec2>& a,
                const std::vector<Vec2>& b, Search& search)
{
    if (owner.size() < 2)
        return; // a point has no edges
    for (std::size_t i = 0; i < owner.size(); ++i)
    {
        const AxisOverlap result =
            overlapOnAxis(a, b, edgeAxis(owner[i], owner[(i + 1) % owner.size()]));
        const bool first = !search.anyAxis;
        search.anyAxis = true;
        if (result.apart)
        {
            // Keep the widest gap: the clearest picture of the separation.
            if (!search.separated || -result.overlap > search.largestGap)
            {
                search.largestGap = -result.overlap;
                search.gapAxis = result.towardsA;
            }
            search.separated = true;
        }
        else if (first || result.overlap < search.leastOverlap ||
                 (result.overlap == search.leastOverlap &&
                  std::fabs(result.towardsA.x) > std::fabs(search.overlapAxis.x)))
        {
            // Ties go to the more horizontal axis (the x axis, as in boxVsBoxContact), then
            // to the axis tried first.
            search.leastOverlap = result.overlap;
            search.overlapAxis = result.towardsA;
            search.overlapAxisIsAnEdgeOfB = ownerIsB;
        }
    }
}

// The point of `points` furthest along `direction`.
Vec2 supportPoint(const std::vector<Vec2>& points, Vec2 direction)
{
    Vec2 best = points[0];
    for (Vec2 point : points)
        if (dot(point, direction) > dot(best, direction))
            best = point;
    return best;
}

// cos and sin of an angle in degrees, exact for whole quarter turns (so a box turned by 90
// degrees has exactly the corners of the unturned box with its sides swapped).
Vec2 cosSinOfDegrees(float degrees)
{
    const double turned = std::fmod(double(degrees), 360.0);
    const double quarter = turned / 90.0;
    if (quarter == std::floor(quarter))
    {
        const int quarterTurns = (static_cast<int>(quarter) % 4 + 4) % 4;
        const float cosines[4] = {1.f, 0.f, -1.f, 0.f};
        const float sines[4] = {0.f, 1.f, 0.f, -1.f};
        return {cosines[quarterTurns], sines[quarterTurns]};
    }
    const double radians = turned * 3.14159265358979323846 / 180.0;
    return {static_cast<float>(std::cos(radians)), static_cast<float>(std::sin(radians))};
}

// Try the axis at right angles to every edge of both shapes (Ericson, Real-Time
// Collision Detection, 5.2.1). One axis where the shadows do not overlap is enough.
Search searchAxes(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    Search search;
    tryEdgesOf(a, false, a, b, search);
    tryEdgesOf(b, true, a, b, search);
    return search;
}

// Nothing to compare (an empty polygon) or nothing to share (two shapes with no area).
bool neverCollide(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
    return a.empty() || b.empty() || (twiceSignedAreaOf(a) == 0.f && twiceSignedAreaOf(b) == 0.f);
}

} // namespace

Polygon toPolygon(const OrientedBox& box)
{
    const Vec2 cosSin = cosSinOfDegrees(box.angleDegrees);
    const float halfWidth = std::fabs(box.halfSize.x);
    const float halfHeight = std::fabs(box.halfSize.y);
    Polygon polygon;
    for (Vec2 corner : {Vec2(-halfWidth, -halfHeight), Vec2(-halfWidth, halfHeight),
                        Vec2(halfWidth, halfHeight), Vec2(halfWidth, -halfHeight)})
    {
        // The rotation sf::Transform::rotate uses: clockwise on screen for a positive angle.
        const Vec2 turned(corner.x * cosSin.x - corner.y * cosSin.y,
                          corner.x * cosSin.y + corner.y * cosSin.x);
        polygon.points.push_back(box.center + turned);
    }
    return polygon;
}

Polygon toPolygon(const Box& box)
{
    const Box b = normalised(box);
    return Polygon{
        {{b.left, b.top}, {b.left, bottomOf(b)}, {rightOf(b), bottomOf(b)}, {rightOf(b), b.top}}};
}

float twiceSignedArea(const Polygon& polygon)
{
    return twiceSignedAreaOf(cleaned(polygon));
}

AxisReport findSeparatingAxis(const Polygon& first, const Polygon& second)
{
    AxisReport report;
    const std::vector<Vec2> a = cleaned(first);
    const std::vector<Vec2> b = cleaned(second);
    if (neverCollide(a, b))
        return report;
    const Search search = searchAxes(a, b);
    if (!search.anyAxis)
        return report;
    report.separated = search.separated;
    report.axis = search.separated ? search.gapAxis : search.overlapAxis;
    report.gap = search.separated ? search.largestGap : -search.leastOverlap;
    return report;
}

Contact polygonVsPolygon(const Polygon& first, const Polygon& second)
{
    Contact contact;
    const std::vector<Vec2> a = cleaned(first);
    const std::vector<Vec2> b = cleaned(second);
    if (neverCollide(a, b))
        return contact;
    const Search search = searchAxes(a, b);
    if (search.separated || !search.anyAxis)
        return contact;
    // The axis of least overlap is the minimum translation.
    contact.hit = true;
    contact.normal = search.overlapAxis;
    contact.depth = search.leastOverlap;
    // The contact point: when the face hit is B's, A's deepest point moved onto that face;
    // when it is A's, B's deepest point (which already lies on B).
    if (search.overlapAxisIsAnEdgeOfB)
        contact.point = supportPoint(a, -contact.normal) + contact.normal * contact.depth;
    else
        contact.point = supportPoint(b, contact.normal);
    return contact;
}

Contact orientedBoxVsOrientedBox(const OrientedBox& a, const OrientedBox& b)
{
    return polygonVsPolygon(toPolygon(a), toPolygon(b));
}

bool pointInPolygon(Vec2 point, const Polygon& polygon)
{
    const std::vector<Vec2> points = cleaned(polygon);
    const float area = twiceSignedAreaOf(points);
    if (area == 0.f || !isFinite(point))
        return false;
    // Strictly on the inner side of every edge (the inner side depends on the winding).
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const Vec2 edge = points[(i + 1) % points.size()] - points[i];
        if (!(cross(edge, point - points[i]) * area > 0.f))
            return false;
    }
    return true;
}

Contact circleVsPolygon(const Circle& circle, const Polygon& polygon)
{
    Contact contact;
    const std::vector<Vec2> points = cleaned(polygon);
    if (points.empty() || !isFinite(circle) || circle.radius < 0.f)
        return contact;
    const float area = twiceSignedAreaOf(points);
    const bool inside = pointInPolygon(circle.center, polygon);

    // The closest point of the polygon's outline to the centre, and the edge it is on.
    Vec2 closest = points[0];
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const Vec2 onEdge =
            closestPointOnSegment(circle.center, points[i], points[(i + 1) % points.size()]);
        if (length(circle.center - onEdge) < length(circle.center - closest))
        {
            closest = onEdge;
        }
    }
    const Vec2 fromPolygon = circle.center - closest;
    const float distance = length(fromPolygon);

    if (!inside && distance > 0.f)
    {
        // Centre outside: like circleVsBoxContact, push along the line from the closest point.
        if (!(distance < circle.radius))
            return contact;
        contact.hit = true;
        contact.normal = fromPolygon / distance;
        contact.depth = circle.radius - distance;
        contact.point = closest;
        return contact;
    }
    if (!inside && !(circle.radius > 0.f))
        return contact; // a point on the outline is outside (the edge rule)

    contact.hit = true;
    if (area == 0.f)
    {
        // Centre exactly on a polygon with no area (a point or a segment): push across it.
        const Vec2 along = points.size() > 1 ? points[1] - points[0] : Vec2();
        contact.normal = unitVectorOr(-perpendicular(along), {-1.f, 0.f});
        contact.depth = circle.radius;
        contact.point = circle.center;
        return contact;
    }
    // Centre inside (or on the outline): leave through the nearest edge. Ties: the first edge.
    float nearest = -1.f;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const Vec2 edge = points[(i + 1) % points.size()] - points[i];
        // Outward normal: the inner side is where cross(edge, p) * area > 0.
        const Vec2 outward =
            unitVectorOr(area > 0.f ? Vec2(edge.y, -edge.x) : Vec2(-edge.y, edge.x), {-1.f, 0.f});
        const float toEdge = -dot(circle.center - points[i], outward);
        if (nearest < 0.f || toEdge < nearest)
        {
            nearest = std::fmax(toEdge, 0.f);
            contact.normal = outward;
        }
    }
    contact.depth = circle.radius + nearest;
    contact.point = circle.center + contact.normal * nearest;
    return contact;
}

Contact polygonVsCircle(const Polygon& polygon, const Circle& circle)
{
    Contact contact = circleVsPolygon(circle, polygon);
    if (contact.hit)
    {
        // Seen from the polygon: out of the circle towards the polygon, point on the circle.
        contact.normal = -contact.normal;
        contact.point = circle.center + contact.normal * circle.radius;
    }
    return contact;
}

} // namespace hitbox
