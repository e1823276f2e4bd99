#include "hitbox/geometry/Polygon.h"

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

// cross(b - a, c - a) in double: > 0 when a, b, c turn clockwise on screen, 0 when in line.
// Measured from `a`, so far from the origin the big terms do not cancel.
double turn(Vec2 a, Vec2 b, Vec2 c)
{
    return (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
}

double twiceSignedAreaOf(const std::vector<Vec2>& points)
{
    double sum = 0.0;
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
        sum += turn(points[0], points[i], points[i + 1]);
    return sum;
}

// The polygon as the tests use it: the corners of its convex hull, in order, by Andrew's
// monotone chain (A. M. Andrew, "Another efficient algorithm for convex hulls in two
// dimensions", 1979). Repeated points, corners in line with their neighbours and dents (a
// concave polygon, or a convex one made slightly concave by rounding) go, so every corner
// turns the same way, which SupportWalk needs. A polygon with no area keeps its two ends (or
// its one point). Empty when a point is out of range or NaN.
std::vector<Vec2> cleaned(const Polygon& polygon)
{
    std::vector<Vec2> points = polygon.points;
    for (Vec2 point : points)
        if (!withinExactRange(point))
            return {};
    std::sort(points.begin(), points.end(),
              [](Vec2 p, Vec2 q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3)
        return points;
    // The lower chain from left to right, then the upper chain back: a corner where the chain
    // does not turn (in line, or turning the other way) is dropped.
    std::vector<Vec2> hull;
    for (int chain = 0; chain < 2; ++chain)
    {
        const std::size_t chainStart = hull.size();
        for (Vec2 point : points)
        {
            while (hull.size() >= chainStart + 2 &&
                   turn(hull[hull.size() - 2], hull.back(), point) <= 0.0)
                hull.pop_back();
            hull.push_back(point);
        }
        hull.pop_back(); // the chain's last point is where the other chain starts
        std::reverse(points.begin(), points.end());
    }
    return hull;
}

// The shadow of a polygon on an axis (not necessarily of unit length).
struct Shadow
{
    double min;
    double max;
};

// A polygon's shadow from two walks: one for its far end, one for its near end.
Shadow shadowOn(SupportWalk& furthest, SupportWalk& nearest, Vec2 axis)
{
    return {-nearest.furthestAlong(-axis), furthest.furthestAlong(axis)};
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
// One axis of the separating axis theorem, given both shadows on it. Their overlap is how
// far A must move along the axis to get clear of B; an overlap that does not penetrate (a
// gap, or shadows that only touch) means this axis separates the shapes.
struct AxisOverlap
{
    bool apart;
    float overlap; // pixels; minus the gap when apart
    Vec2 towardsA; // unit: the way to move A (from B's side to A's side)
};

AxisOverlap overlapOnAxis(Shadow shadowA, Shadow shadowB, Vec2 axis)
{
    // How far A must move along +axis, or along -axis, to clear B.
    const double pushPositive = shadowB.max - shadowA.min;
    const double pushNegative = shadowA.max - shadowB.min;
    // Equal pushes go the negative way (left or up), as boxVsBoxContact does.
    const bool negative = pushNegative <= pushPositive;
    const double push = negative ? pushNegative : pushPositive;
    const float overlap = static_cast<float>(push / length(axis)); // pixels
    const Vec2 unit = unitVectorOr(axis, {0.f, 0.f});
    // (+ 0.f turns a -0 into 0, so an axis-aligned normal prints and compares cleanly.)
    const Vec2 towardsA = negative ? Vec2(-unit.x + 0.f, -unit.y + 0.f) : unit;
    return {!penetrates(overlap), overlap, towardsA};
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
    // The edges' axes turn steadily round the owner: each walk goes on from the last edge's.
    SupportWalk aFurthest{a}, aNearest{a}, bFurthest{b}, bNearest{b};
    for (std::size_t i = 0; i < owner.size(); ++i)
    {
        const Vec2 axis = edgeAxis(owner[i], owner[(i + 1) % owner.size()]);
        const AxisOverlap result = overlapOnAxis(shadowOn(aFurthest, aNearest, axis),
                                                 shadowOn(bFurthest, bNearest, axis), axis);
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
    const double radians = turned * piDouble / 180.0;
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
    return a.empty() || b.empty() || (twiceSignedAreaOf(a) == 0.0 && twiceSignedAreaOf(b) == 0.0);
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

Polygon convexHull(const Polygon& polygon)
{
    return Polygon{cleaned(polygon)};
}

float twiceSignedArea(const Polygon& polygon)
{
    return static_cast<float>(twiceSignedAreaOf(cleaned(polygon)));
}

namespace
{
// Both polygons cleaned into `a` and `b`, and the search over their axes; false when there is
// nothing to search (a pair that never collides, or no axis at all).
bool searchPolygons(const Polygon& first, const Polygon& second, std::vector<Vec2>& a,
                    std::vector<Vec2>& b, Search& search)
{
    a = cleaned(first);
    b = cleaned(second);
    if (neverCollide(a, b))
        return false;
    search = searchAxes(a, b);
    return search.anyAxis;
}
} // namespace

AxisReport findSeparatingAxis(const Polygon& first, const Polygon& second)
{
    AxisReport report;
    std::vector<Vec2> a, b;
    Search search;
    if (!searchPolygons(first, second, a, b, search))
        return report;
    report.separated = search.separated;
    report.axis = search.separated ? search.gapAxis : search.overlapAxis;
    report.gap = search.separated ? search.largestGap : -search.leastOverlap;
    return report;
}

Contact polygonVsPolygon(const Polygon& first, const Polygon& second)
{
    Contact contact;
    std::vector<Vec2> a, b;
    Search search;
    if (!searchPolygons(first, second, a, b, search) || search.separated)
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
    const double area = twiceSignedAreaOf(points);
    if (area == 0.0 || !withinExactRange(point))
        return false;
    // Strictly on the inner side of every edge (the inner side depends on the winding).
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!(turn(points[i], points[(i + 1) % points.size()], point) * area > 0.0))
            return false;
    return true;
}

namespace
{
// The point of a convex outline closest to `centre`, its distance, and the way out there.
struct OutlinePoint
{
    Vec2 point;
    float distance = 0.f;
    Vec2 normal{-1.f, 0.f}; // unit
};

// Found edge by edge in double. When the closest point lies inside an edge, the way out is
// the edge's own outward normal and the distance the centre's height above the edge: the line
// from a projected point to a centre within rounding of the edge is rounding noise pointing
// anywhere, and a push along it can leave the circle inside (issue 25: about 2 in 10^6). Only
// at a corner is the way out the line from the corner (an exact difference of floats, so it
// points into the corner's outer wedge). `area` gives the winding: the inner side of an edge
// is where turn() * area > 0.
OutlinePoint closestOnOutline(Vec2 centre, const std::vector<Vec2>& points, double area)
{
    OutlinePoint best;
    double bestSquared = -1.0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const Vec2 from = points[i];
        const Vec2 to = points[(i + 1) % points.size()];
        const double edgeX = double(to.x) - from.x, edgeY = double(to.y) - from.y;
        const double lengthSquared = edgeX * edgeX + edgeY * edgeY;
        const double along =
            lengthSquared > 0.0
                ? ((double(centre.x) - from.x) * edgeX + (double(centre.y) - from.y) * edgeY) /
                      lengthSquared
                : 0.0;
        OutlinePoint candidate;
        double squared;
        if (along <= 0.0 || along >= 1.0)
        {
            const Vec2 corner = along <= 0.0 ? from : to;
            const double dx = double(centre.x) - corner.x, dy = double(centre.y) - corner.y;
            squared = dx * dx + dy * dy;
            candidate.point = corner;
            candidate.distance = static_cast<float>(std::sqrt(squared));
            candidate.normal = unitVectorOr(centre - corner, {-1.f, 0.f});
        }
        else
        {
            const double height =
                -turn(from, to, centre) * (area > 0.0 ? 1.0 : -1.0) / std::sqrt(lengthSquared);
            squared = height * height;
            candidate.point = Vec2(static_cast<float>(from.x + along * edgeX),
                                   static_cast<float>(from.y + along * edgeY));
            candidate.distance = static_cast<float>(std::fabs(height));
            // Outward; towards the centre on a polygon with no area (a segment has two sides).
            const Vec2 edge = to - from;
            const Vec2 outward = unitVectorOr(
                area > 0.0 ? Vec2(edge.y, -edge.x) : Vec2(-edge.y, edge.x), {-1.f, 0.f});
            candidate.normal = height < 0.0 ? -outward : outward;
        }
        if (bestSquared < 0.0 || squared < bestSquared)
        {
            bestSquared = squared;
            best = candidate;
        }
    }
    return best;
}
} // namespace

Contact circleVsPolygon(const Circle& circle, const Polygon& polygon)
{
    Contact contact;
    const std::vector<Vec2> points = cleaned(polygon);
    if (points.empty() || !withinExactRange(circle.center) || !withinExactRange(circle.radius) ||
        circle.radius < 0.f)
        return contact;
    const double area = twiceSignedAreaOf(points);
    const bool inside = pointInPolygon(circle.center, polygon);

    const OutlinePoint outline = closestOnOutline(circle.center, points, area);
    if (!inside && outline.distance > 0.f)
    {
        // Centre outside: like circleVsBoxContact, push out along the way from the closest
        // point (an edge's own normal, or the line from a corner).
        contact.depth = circle.radius - outline.distance;
        if (!penetrates(contact.depth))
            return Contact{};
        contact.hit = true;
        contact.normal = outline.normal;
        contact.point = outline.point;
        return contact;
    }
    if (!inside && !penetrates(circle.radius))
        return contact; // a point on the outline is outside (the edge rule)

    contact.hit = true;
    if (area == 0.0)
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
            unitVectorOr(area > 0.0 ? Vec2(edge.y, -edge.x) : Vec2(-edge.y, edge.x), {-1.f, 0.f});
        const float toEdge = -dot(circle.center - points[i], outward);
        if (nearest < 0.f || toEdge < nearest)
        {
            nearest = std::fmax(toEdge, 0.f);
            contact.normal = outward;
        }
    }
    contact.depth = circle.radius + nearest;
    // A point whose way out rounds to 0 is touching, not inside (the edge rule).
    if (!penetrates(contact.depth))
        return Contact{};
    contact.point = circle.center + contact.normal * nearest;
    return contact;
}

} // namespace hitbox
