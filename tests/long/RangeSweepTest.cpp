// RangeSweepTest.cpp - the polygon, oriented box, circle-polygon and capsule tests over the
// whole range they promise (Range.h: coordinates within +-1e6 px), at every scale from 1 px
// shapes to 1e6 px ones, against the double-precision references of GeometryReference.h, and
// beyond the range, where the answer must be "no hit". Label `long`.
//
// TOLERANCE: 1e-6 of the largest coordinate of the two shapes (at least 1e-4 px): what
// Range.h promises. Cases whose reference depth is within it of 0 are not judged.
#include "hitbox/geometry/Capsule.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Vec2.h"
#include "support/GeometryReference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using reference::Point;
using reference::toPoint;
using Corner = reference::Vec<double>;

constexpr long cases = 300000;

struct Sweep
{
    std::mt19937 random;
    long cases = 0, hits = 0, unjudged = 0, failures = 0;
    double worstError = 0.0; // the largest |depth - reference| seen, as a share of the scale

    explicit Sweep(unsigned seed) : random(seed) {}
    double uniform(double low, double high)
    {
        return std::uniform_real_distribution<double>(low, high)(random);
    }
    // Log-uniform: every scale from `low` to `high` equally often.
    double scale(double low, double high) { return low * std::pow(high / low, uniform(0, 1)); }

    void fail(const std::string& what)
    {
        if (++failures <= 10)
            ADD_FAILURE() << what;
    }
    // Judges one contact against the reference depth (> 0: overlap), at scale `largest`.
    void judge(const hitbox::Contact& contact, double depth, double largest,
               const std::string& name)
    {
        ++cases;
        const double tolerance = std::max(1e-4, 1e-6 * largest);
        if (contact.hit)
        {
            if (!(std::isfinite(contact.depth) && contact.depth > 0.f) ||
                !hitbox::isFinite(contact.point) ||
                std::fabs(hitbox::length(contact.normal) - 1.f) > 1e-6f)
                fail(name + ": a hit with depth " + std::to_string(contact.depth) +
                     " or a normal that is not unit");
        }
        if (std::fabs(depth) < tolerance)
        {
            ++unjudged;
            return;
        }
        hits += depth > 0;
        if (contact.hit != (depth > 0))
            return fail(name + ": says " + (contact.hit ? "hit" : "miss") + ", reference depth " +
                        std::to_string(depth) + " at scale " + std::to_string(largest));
        if (!contact.hit)
            return;
        worstError =
            std::max(worstError, std::fabs(contact.depth - depth) / std::max(1.0, largest));
        if (std::fabs(contact.depth - depth) > tolerance)
            fail(name + ": depth " + std::to_string(contact.depth) + ", reference " +
                 std::to_string(depth) + " at scale " + std::to_string(largest));
    }
    void expectSound(const char* what) const
    {
        EXPECT_EQ(failures, 0);
        EXPECT_LT(unjudged * 20, cases) << unjudged << " cases within the tolerance of touching";
        EXPECT_GT(hits * 10, cases) << "too few hits to mean anything";
        EXPECT_LT(hits * 10, cases * 9) << "too few misses to mean anything";
        std::cout << "[ range ] " << what << ": " << cases << " cases, " << hits << " hits, "
                  << unjudged << " not judged; worst depth error " << worstError
                  << " of the scale\n";
    }
};

double largestCoordinate(const hitbox::Polygon& polygon)
{
    double largest = 1.0;
    for (hitbox::Vec2 p : polygon.points)
        largest = std::max({largest, double(std::fabs(p.x)), double(std::fabs(p.y))});
    return largest;
}

// A convex polygon (a turned box 3 times in 10) of radius `size` round `centre`.
hitbox::Polygon randomPolygon(Sweep& sweep, Corner centre, double size)
{
    const auto at = [](double x, double y) { return hitbox::Vec2(float(x), float(y)); };
    if (sweep.uniform(0, 1) < 0.3)
        return hitbox::toPolygon(hitbox::OrientedBox{
            at(centre.x, centre.y),
            at(size * sweep.uniform(0.05, 0.7), size * sweep.uniform(0.05, 0.7)),
            float(sweep.uniform(0, 360))});
    std::vector<Corner> points;
    const int count = std::uniform_int_distribution<int>(3, 8)(sweep.random);
    for (int k = 0; k < count; ++k)
    {
        const double angle = sweep.uniform(0, 2.0 * hitbox::piDouble);
        const double r = size * std::sqrt(sweep.uniform(0.05, 1));
        points.push_back({double(float(centre.x + r * std::cos(angle))),
                          double(float(centre.y + r * std::sin(angle)))});
    }
    hitbox::Polygon polygon;
    for (Corner p : reference::convexHull(points))
        polygon.points.push_back(at(p.x, p.y));
    if (sweep.uniform(0, 1) < 0.5)
        std::reverse(polygon.points.begin(), polygon.points.end());
    return polygon;
}

std::vector<Corner> corners(const hitbox::Polygon& polygon)
{
    std::vector<Corner> result;
    for (hitbox::Vec2 p : polygon.points)
        result.push_back({p.x, p.y});
    return result;
}

std::vector<Point> points(const hitbox::Polygon& polygon)
{
    std::vector<Point> result;
    for (hitbox::Vec2 p : polygon.points)
        result.push_back({p.x, p.y});
    return result;
}

// Two shapes' centres: the first anywhere that keeps a shape of `size` in range (as far from
// the origin at every scale from the size to the range), the second within about two sizes
// of it (so many pairs overlap).
void randomCentres(Sweep& sweep, double size, Corner& first, Corner& second)
{
    const double room = hitbox::exactRange - 2.0 * size;
    const double reach = sweep.scale(std::min(2.0 * size + 1.0, room), room);
    first = {sweep.uniform(-reach, reach), sweep.uniform(-reach, reach)};
    second = {std::clamp(first.x + sweep.uniform(-2, 2) * size, -room, room),
              std::clamp(first.y + sweep.uniform(-2, 2) * size, -room, room)};
}

hitbox::Polygon moved(hitbox::Polygon polygon, hitbox::Vec2 offset)
{
    for (hitbox::Vec2& p : polygon.points)
        p += offset;
    return polygon;
}
} // namespace

TEST(GeometryRangeSweep, PolygonsAndOrientedBoxesAtEveryScaleInTheRange)
{
    Sweep sweep(201u);
    Sweep swapped(0u);
    for (long i = 0; i < cases && sweep.failures < 10; ++i)
    {
        const double size = sweep.scale(0.5, 2.5e5);
        Corner centreA, centreB;
        randomCentres(sweep, size, centreA, centreB);
        const hitbox::Polygon a = randomPolygon(sweep, centreA, size);
        const hitbox::Polygon b = randomPolygon(sweep, centreB, size * sweep.uniform(0.2, 1));
        const double largest = std::max(largestCoordinate(a), largestCoordinate(b));
        const double depth =
            reference::originDepth(reference::minkowskiDifference(corners(a), corners(b)));
        const hitbox::Contact contact = hitbox::polygonVsPolygon(a, b);
        sweep.judge(contact, depth, largest, "polygonVsPolygon");
        // Swapped: the same depth, the normal reversed.
        const hitbox::Contact back = hitbox::polygonVsPolygon(b, a);
        swapped.judge(back, depth, largest, "polygonVsPolygon swapped");
        if (contact.hit && back.hit && std::fabs(contact.depth - back.depth) > 1e-6 * largest)
            sweep.fail("swapping the shapes changed the depth");
        // Moved (both together, staying in range): the same answer within the tolerance.
        const hitbox::Vec2 offset(float(sweep.uniform(-1, 1) * (hitbox::exactRange - largest)),
                                  float(sweep.uniform(-1, 1) * (hitbox::exactRange - largest)));
        const hitbox::Polygon movedA = moved(a, offset);
        const hitbox::Polygon movedB = moved(b, offset);
        const double movedLargest = std::max(largestCoordinate(movedA), largestCoordinate(movedB));
        const double movedDepth = reference::originDepth(
            reference::minkowskiDifference(corners(movedA), corners(movedB)));
        const hitbox::Contact movedContact = hitbox::polygonVsPolygon(movedA, movedB);
        if (std::fabs(movedDepth) > 1e-6 * movedLargest && std::fabs(depth) > 1e-6 * movedLargest &&
            (movedContact.hit != contact.hit ||
             std::fabs(movedContact.depth - contact.depth) > 2e-6 * movedLargest))
            sweep.fail("moving both shapes by " + std::to_string(offset.x) + ", " +
                       std::to_string(offset.y) + " changed the answer");
    }
    sweep.expectSound("polygonVsPolygon");
    EXPECT_EQ(swapped.failures, 0);
}

TEST(GeometryRangeSweep, CirclesAgainstPolygonsAtEveryScaleInTheRange)
{
    Sweep sweep(202u);
    for (long i = 0; i < cases && sweep.failures < 10; ++i)
    {
        const double size = sweep.scale(0.5, 2.5e5);
        Corner centreA, centreB;
        randomCentres(sweep, size, centreA, centreB);
        const hitbox::Circle circle{{float(centreA.x), float(centreA.y)},
                                    float(size * sweep.uniform(0, 1))};
        const hitbox::Polygon polygon = randomPolygon(sweep, centreB, size);
        // Reference: the radius minus the distance to the outline, or plus it when inside.
        const std::vector<Point> outline = points(polygon);
        const Point centre = toPoint(circle.center);
        const double distance = reference::segmentPolygonDistance(centre, centre, outline);
        double inside = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < outline.size(); ++k)
            inside = std::min(inside, reference::pointSegmentDistance(
                                          centre, outline[k], outline[(k + 1) % outline.size()]));
        const double depth = distance > 0 ? circle.radius - distance : circle.radius + inside;
        const double largest =
            std::max({largestCoordinate(polygon), double(std::fabs(circle.center.x)),
                      double(std::fabs(circle.center.y)), double(circle.radius)});
        sweep.judge(hitbox::circleVsPolygon(circle, polygon), depth, largest, "circleVsPolygon");
    }
    sweep.expectSound("circleVsPolygon");
}

TEST(GeometryRangeSweep, CapsulesAtEveryScaleInTheRange)
{
    Sweep sweep(203u);
    for (long i = 0; i < cases && sweep.failures < 10; ++i)
    {
        const double size = sweep.scale(0.5, 2.5e5);
        Corner centreA, centreB;
        randomCentres(sweep, size, centreA, centreB);
        const auto capsuleAt = [&](Corner centre)
        {
            const double angle = sweep.uniform(0, 2.0 * hitbox::piDouble);
            const double half = size * sweep.uniform(0, 1);
            const hitbox::Vec2 along(float(half * std::cos(angle)), float(half * std::sin(angle)));
            const hitbox::Vec2 middle(float(centre.x), float(centre.y));
            return hitbox::Capsule{middle - along, middle + along,
                                   float(size * sweep.uniform(0.05, 1))};
        };
        const hitbox::Capsule a = capsuleAt(centreA);
        const hitbox::Capsule b = capsuleAt(centreB);
        const double core = reference::segmentDistance(toPoint(a.start), toPoint(a.end),
                                                       toPoint(b.start), toPoint(b.end));
        double largest = 1.0;
        for (hitbox::Vec2 p : {a.start, a.end, b.start, b.end})
            largest = std::max({largest, double(std::fabs(p.x)), double(std::fabs(p.y))});
        const hitbox::Contact contact = hitbox::capsuleVsCapsule(a, b);
        // Cores that cross or nearly touch (within rounding, Capsule.h) push a separating, not
        // always the shortest, way: only hit or miss is judged there.
        const double depth = double(a.radius) + b.radius - core;
        if (core > 2e-6 * largest)
            sweep.judge(contact, depth, largest, "capsuleVsCapsule");
        else if (std::fabs(depth) > 1e-6 * largest && contact.hit != (depth > 0))
            sweep.fail("capsuleVsCapsule with cores crossing or within rounding: says " +
                       std::string(contact.hit ? "hit" : "miss") + ", reference depth " +
                       std::to_string(depth));
    }
    sweep.expectSound("capsuleVsCapsule");
}

TEST(GeometryRangeSweep, BeyondTheRangeNothingCollides)
{
    // Shapes out to 1e30 px, or up to 1e30 px long: when any input of a test is out of the
    // range, "no hit", never NaN.
    Sweep sweep(204u);
    const auto out = [](hitbox::Vec2 p) { return !hitbox::withinExactRange(p); };
    const auto outPolygon = [](const hitbox::Polygon& polygon)
    { return largestCoordinate(polygon) > hitbox::exactRange; };
    long judged = 0;
    for (long i = 0; i < cases / 10 && sweep.failures < 10; ++i)
    {
        const double far = sweep.scale(2e6, 1e30);
        const double size = sweep.scale(1, far);
        const Corner centre{sweep.uniform(-far, far), sweep.uniform(-far, far)};
        const hitbox::Polygon a = randomPolygon(sweep, centre, size);
        const hitbox::Polygon b = randomPolygon(sweep, {centre.x + size * 0.1, centre.y}, size);
        const hitbox::Vec2 c(float(centre.x), float(centre.y));
        const float radius = float(size);
        const std::string where = " beyond the range at " + std::to_string(far);
        if (outPolygon(a) || outPolygon(b))
        {
            ++judged;
            if (hitbox::polygonVsPolygon(a, b).hit)
                sweep.fail("polygonVsPolygon: a hit" + where);
        }
        if (out(c) || !hitbox::withinExactRange(radius) || outPolygon(b))
        {
            ++judged;
            if (hitbox::circleVsPolygon(hitbox::Circle{c, radius}, b).hit ||
                hitbox::capsuleVsPolygon(hitbox::Capsule{c, a.points.front(), radius}, b).hit)
                sweep.fail("circleVsPolygon or capsuleVsPolygon: a hit" + where);
        }
        const hitbox::Capsule first{a.points.front(), a.points.back(), radius};
        const hitbox::Capsule second{b.points.front(), b.points.back(), radius};
        if (out(first.start) || out(first.end) || out(second.start) || out(second.end) ||
            !hitbox::withinExactRange(radius))
        {
            ++judged;
            if (hitbox::capsuleVsCapsule(first, second).hit)
                sweep.fail("capsuleVsCapsule: a hit" + where);
        }
    }
    EXPECT_EQ(sweep.failures, 0);
    EXPECT_GT(judged, cases / 10);
}
