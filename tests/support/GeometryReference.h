// GeometryReference.h - independent answers to check the geometry functions against.
//
// Every reference here works a different way from the code it checks, in double precision:
//   - sweeps: a brute force that walks along the motion in steps of at most 0.5 px and asks
//     the plain "how deep do they overlap here?" question at every step;
//   - polygons: edge crossings + point-in-polygon, and the Minkowski difference (the convex
//     hull of every corner of A minus every corner of B: the shapes overlap exactly when the
//     origin lies strictly inside it, and the distance from the origin to its outline is the
//     penetration depth); no shadows, no separating axes;
//   - capsules: segment distance as the smallest of four point-to-segment distances plus a
//     crossing test, instead of the closest-point formula.
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace reference
{

struct Point
{
    double x;
    double y;
};

inline Point operator-(Point a, Point b)
{
    return {a.x - b.x, a.y - b.y};
}
inline Point operator+(Point a, Point b)
{
    return {a.x + b.x, a.y + b.y};
}
inline Point operator*(Point a, double s)
{
    return {a.x * s, a.y * s};
}
inline double dot(Point a, Point b)
{
    return a.x * b.x + a.y * b.y;
}
inline double cross(Point a, Point b)
{
    return a.x * b.y - a.y * b.x;
}
inline double length(Point a)
{
    return std::hypot(a.x, a.y);
}
inline Point toPoint(hitbox::Vec2 v)
{
    return {v.x, v.y};
}

// ---- penetration depth of still shapes (> 0: they share area) ----------------------------

// Circles: radii added minus the distance between the centres.
inline double circlePenetration(Point a, double radiusA, Point b, double radiusB)
{
    return radiusA + radiusB - length(a - b);
}

// Signed distance from a point to a box: negative inside (the usual formula for a box
// centred at the origin, after moving the point).
inline double signedDistanceToBox(Point p, const hitbox::Box& box)
{
    const double left = std::min<double>(box.left, double(box.left) + box.width);
    const double top = std::min<double>(box.top, double(box.top) + box.height);
    const double halfWidth = std::fabs(double(box.width)) / 2.0;
    const double halfHeight = std::fabs(double(box.height)) / 2.0;
    const double dx = std::fabs(p.x - (left + halfWidth)) - halfWidth;
    const double dy = std::fabs(p.y - (top + halfHeight)) - halfHeight;
    const double outside = std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
    const double inside = std::min(std::max(dx, dy), 0.0);
    return outside + inside;
}

// Two boxes (the mover's top-left moved by `offset`): the smaller of the two axis overlaps.
inline double boxPenetration(const hitbox::Box& a, Point offset, const hitbox::Box& b)
{
    const double aLeft = std::min<double>(a.left, double(a.left) + a.width) + offset.x;
    const double aTop = std::min<double>(a.top, double(a.top) + a.height) + offset.y;
    const double aRight = aLeft + std::fabs(double(a.width));
    const double aBottom = aTop + std::fabs(double(a.height));
    const double bLeft = std::min<double>(b.left, double(b.left) + b.width);
    const double bTop = std::min<double>(b.top, double(b.top) + b.height);
    const double bRight = bLeft + std::fabs(double(b.width));
    const double bBottom = bTop + std::fabs(double(b.height));
    const double overlapX = std::min(aRight - bLeft, bRight - aLeft);
    const double overlapY = std::min(aBottom - bTop, bBottom - aTop);
    return std::min(overlapX, overlapY);
}

// ---- the brute force along a motion -------------------------------------------------------

// What walking along the motion found. `penetration(s)` is the overlap depth at time s in
// [0, 1]; `speed` is how many pixels the shapes move relative to each other over the whole
// step (the depth can change by at most that much per unit of time, since every depth here
// is a distance: that is what makes skipping ahead safe).
struct Walk
{
    bool hits = false;       // some sample overlaps by more than the tolerance
    bool misses = false;     // no time in [0, 1] can overlap by more than -tolerance
    double firstHit = -1.0;  // time of the first sample that overlaps by more than the tolerance
    double stepPixels = 0.0; // how far apart the samples are along the motion
};

template <class Penetration>
Walk walkAlong(Penetration penetration, double speed, double tolerance)
{
    Walk walk;
    const double maxStepPixels = 0.5;
    const long samples = std::max(64L, static_cast<long>(std::ceil(speed / maxStepPixels)));
    walk.stepPixels = speed / double(samples);
    double highest = -std::numeric_limits<double>::infinity();
    for (long k = 0; k <= samples;)
    {
        const double time = double(k) / double(samples);
        const double depth = penetration(time);
        highest = std::max(highest, depth);
        if (depth > tolerance)
        {
            walk.hits = true;
            walk.firstHit = time;
            return walk;
        }
        // Far from overlapping: the next samples cannot overlap either (each is at most
        // stepPixels deeper than the one before), so skip those that stay below -stepPixels.
        long skip = 0;
        if (walk.stepPixels > 0.0 && depth < -2.0 * walk.stepPixels)
        {
            skip = static_cast<long>(std::floor((-depth - walk.stepPixels) / walk.stepPixels));
            highest = std::max(highest, -walk.stepPixels);
        }
        k += 1 + skip;
    }
    // Between samples the depth can rise by at most half a step above the highest sample.
    walk.misses = highest + walk.stepPixels / 2.0 < -tolerance;
    return walk;
}

// ---- convex polygons ----------------------------------------------------------------------

// Convex hull by Andrew's monotone chain, anticlockwise in maths axes, collinear points
// dropped. T = double for float polygons, std::int64_t for whole-number polygons (exact).
template <class T>
struct Vec
{
    T x;
    T y;
};

template <class T>
T crossOf(Vec<T> o, Vec<T> a, Vec<T> b)
{
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

template <class T>
std::vector<Vec<T>> convexHull(std::vector<Vec<T>> points)
{
    std::sort(points.begin(), points.end(),
              [](Vec<T> a, Vec<T> b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end(),
                             [](Vec<T> a, Vec<T> b) { return a.x == b.x && a.y == b.y; }),
                 points.end());
    if (points.size() < 3)
        return points;
    std::vector<Vec<T>> hull(2 * points.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        while (k >= 2 && crossOf(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;)
    {
        while (k >= lower && crossOf(hull[k - 2], hull[k - 1], points[i]) <= 0)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

// The Minkowski difference A - B as a convex hull.
template <class T>
std::vector<Vec<T>> minkowskiDifference(const std::vector<Vec<T>>& a, const std::vector<Vec<T>>& b)
{
    std::vector<Vec<T>> differences;
    for (Vec<T> p : a)
        for (Vec<T> q : b)
            differences.push_back({p.x - q.x, p.y - q.y});
    return convexHull(differences);
}

// Exact for whole numbers: is the origin strictly inside the (anticlockwise) hull?
template <class T>
bool originStrictlyInside(const std::vector<Vec<T>>& hull)
{
    if (hull.size() < 3)
        return false;
    const Vec<T> origin{0, 0};
    for (std::size_t i = 0; i < hull.size(); ++i)
        if (!(crossOf(hull[i], hull[(i + 1) % hull.size()], origin) > 0))
            return false;
    return true;
}

// Signed distance from the origin to the outline of the hull: > 0 inside (the penetration
// depth), < 0 outside (minus the gap). `outward` gets the outward normal of the nearest edge
// when inside, and `runnerUp` the second-smallest edge distance (to spot ties).
inline double originDepth(const std::vector<Vec<double>>& hull, Point* outward = nullptr,
                          double* runnerUp = nullptr)
{
    if (hull.empty())
        return -std::numeric_limits<double>::infinity();
    const std::size_t n = hull.size();
    bool inside = n >= 3;
    double nearest = std::numeric_limits<double>::infinity();
    double second = std::numeric_limits<double>::infinity();
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Point a{hull[i].x, hull[i].y};
        const Point b{hull[(i + 1) % n].x, hull[(i + 1) % n].y};
        const Point edge = b - a;
        const double edgeLength = length(edge);
        // Distance from the origin to the edge as a segment (for the outside case).
        const double t =
            edgeLength > 0
                ? std::clamp(dot(Point{0, 0} - a, edge) / (edgeLength * edgeLength), 0.0, 1.0)
                : 0.0;
        gap = std::min(gap, length(a + edge * t));
        if (n < 3 || edgeLength == 0)
            continue;
        const double toLine = cross(edge, Point{0, 0} - a) / edgeLength; // > 0: inner side
        if (toLine <= 0)
            inside = false;
        if (toLine < nearest)
        {
            second = nearest;
            nearest = toLine;
            if (outward)
                *outward = Point{edge.y / edgeLength, -edge.x / edgeLength};
        }
        else if (toLine < second)
        {
            second = toLine;
        }
    }
    if (runnerUp)
        *runnerUp = second;
    return inside ? nearest : -gap;
}

// The classic test for polygons in general position: they overlap when an edge of one
// properly crosses an edge of the other, or a corner of one is strictly inside the other.
inline bool strictlyInsideConvex(Point p, const std::vector<Point>& polygon)
{
    int positive = 0;
    int negative = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
    {
        const double side = cross(polygon[(i + 1) % polygon.size()] - polygon[i], p - polygon[i]);
        positive += side > 0;
        negative += side < 0;
    }
    return positive == int(polygon.size()) || negative == int(polygon.size());
}

inline bool segmentsProperlyCross(Point a, Point b, Point c, Point d)
{
    const double d1 = cross(b - a, c - a);
    const double d2 = cross(b - a, d - a);
    const double d3 = cross(d - c, a - c);
    const double d4 = cross(d - c, b - c);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

inline bool polygonsOverlapByEdges(const std::vector<Point>& a, const std::vector<Point>& b)
{
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j)
            if (segmentsProperlyCross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]))
                return true;
    for (Point p : a)
        if (strictlyInsideConvex(p, b))
            return true;
    for (Point p : b)
        if (strictlyInsideConvex(p, a))
            return true;
    return false;
}

// ---- segments (for capsules) --------------------------------------------------------------

inline double pointSegmentDistance(Point p, Point a, Point b)
{
    const Point ab = b - a;
    const double lengthSquared = dot(ab, ab);
    const double t = lengthSquared > 0 ? std::clamp(dot(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    return length(p - (a + ab * t));
}

// Two segments' distance: 0 when they cross, else the nearest of the four end-to-segment
// distances (in 2D the closest pair always includes an end point).
inline double segmentDistance(Point a, Point b, Point c, Point d)
{
    if (segmentsProperlyCross(a, b, c, d))
        return 0.0;
    return std::min({pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
                     pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)});
}

// Distance from a segment to a convex polygon (as a filled region): 0 when they meet.
inline double segmentPolygonDistance(Point a, Point b, const std::vector<Point>& polygon)
{
    if (polygon.size() >= 3 &&
        (strictlyInsideConvex(a, polygon) || strictlyInsideConvex(b, polygon)))
        return 0.0;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i)
        nearest =
            std::min(nearest, segmentDistance(a, b, polygon[i], polygon[(i + 1) % polygon.size()]));
    return nearest;
}

} // namespace reference
