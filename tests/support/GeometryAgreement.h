// GeometryAgreement.h - seeded random cases checked against the references of
// GeometryReference.h. The default test run calls each check with 10^5 cases
// (tests/geometry/AgreementTest.cpp); the `long` label calls them with 10^6 (tests/long/).
//
// TOLERANCE: 1e-3 px. Inputs are floats up to about 10^4 px, whose rounding step is about
// 10^-3 px at 10^4 and 6e-5 px at 600, so two correct methods can disagree about shapes that
// overlap (or miss) by less than that. Cases whose reference depth is within the tolerance of
// 0 are counted as `ambiguous` and not judged; the tests check they stay rare. Every other
// case must agree exactly on hit/miss. Times are judged by where they put the shapes: at the
// reported time of impact the reference depth must be 0 within 1e-3 px (plus 1e-7 of the
// move's length, the rounding of a float time), and no earlier sample may overlap.
#pragma once

#include "support/GeometryReference.h"
#include "support/Printers.h"

#include "hitbox/geometry/Capsule.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/geometry/SweptCircle.h"
#include "hitbox/geometry/Vec2.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>

namespace agreement
{

constexpr double tolerance = 1e-3; // pixels (see above)

struct Tally
{
    long cases = 0;
    long hits = 0;      // cases where the reference says "they collide"
    long ambiguous = 0; // within the tolerance of touching: not judged
    long failures = 0;
};

// Records a disagreement; only the first few are printed, so a broken function does not
// bury the log under 10^5 messages.
// `scene` describes the case; it is a function so that the text is only built on failure.
template <class Scene>
void fail(Tally& tally, const std::string& what, const Scene& scene)
{
    if (++tally.failures <= 5)
        ADD_FAILURE() << what << "\n  case: " << scene();
}

template <class T>
std::string show(const T& value)
{
    return ::testing::PrintToString(value);
}

inline std::string show(const hitbox::Polygon& polygon)
{
    std::ostringstream out;
    out.precision(9);
    out << "Polygon{";
    for (hitbox::Vec2 p : polygon.points)
        out << "(" << p.x << ", " << p.y << ") ";
    out << "}";
    return out.str();
}

inline std::string show(const hitbox::Capsule& capsule)
{
    std::ostringstream out;
    out.precision(9);
    out << "Capsule{(" << capsule.start.x << ", " << capsule.start.y << ") -> (" << capsule.end.x
        << ", " << capsule.end.y << "), r=" << capsule.radius << "}";
    return out.str();
}

// Random scenes. Mostly continuous values; some whole numbers (exact touching happens
// there); some zero, negative and very large moves.
struct RandomCases
{
    std::mt19937 random;
    explicit RandomCases(unsigned seed) : random(seed) {}

    double uniform(double low, double high)
    {
        return std::uniform_real_distribution<double>(low, high)(random);
    }
    bool chance(double probability) { return uniform(0.0, 1.0) < probability; }
    float value(double low, double high)
    {
        const double v = uniform(low, high);
        return static_cast<float>(chance(0.1) ? std::round(v) : v);
    }
    hitbox::Vec2 position() { return {value(0, 600), value(0, 600)}; }
    float radius() { return chance(0.05) ? 0.f : value(0.5, 80); }
    hitbox::Box box()
    {
        hitbox::Box box(value(0, 600), value(0, 600), value(0.5, 150), value(0.5, 150));
        if (chance(0.05))
        {
            box.left += box.width;
            box.width = -box.width; // the same box, written backwards
        }
        return box;
    }
    hitbox::Vec2 displacement()
    {
        const double kind = uniform(0, 1);
        if (kind < 0.05)
            return {0.f, 0.f};
        if (kind < 0.15)
            return {value(-2, 2), value(-2, 2)};
        if (kind < 0.30)
            return chance(0.5) ? hitbox::Vec2(value(-300, 300), 0.f)
                               : hitbox::Vec2(0.f, value(-300, 300));
        if (kind < 0.40)
        {
            // Up to 10^6 px/s at 120 steps a second.
            const double angle = uniform(0, 2.0 * hitbox::piDouble);
            const double length = uniform(0, 1.0e6 / 120.0);
            return {static_cast<float>(length * std::cos(angle)),
                    static_cast<float>(length * std::sin(angle))};
        }
        return {value(-300, 300), value(-300, 300)};
    }
};

// ---- sweeps against the brute-force walk -------------------------------------------------

// `depthAt(time, offset)`: the reference depth with the mover at `time`, moved by `offset`.
template <class DepthAt, class Scene>
void judgeSweep(Tally& tally, const hitbox::Hit& hit, DepthAt depthAt, double speed,
                const Scene& scene)
{
    using reference::Point;
    ++tally.cases;
    const reference::Walk walk = reference::walkAlong(
        [&](double s) {
            return depthAt(s, Point{0, 0});
        },
        speed, tolerance);
    if (!walk.hits)
    {
        if (!walk.misses)
            ++tally.ambiguous;
        else if (hit.hit)
            fail(tally, "the sweep hits at " + show(hit.time) + ", the brute force never overlaps",
                 scene);
        return;
    }
    ++tally.hits;
    if (!hit.hit)
        return fail(tally,
                    "the sweep misses, the brute force overlaps at time " + show(walk.firstHit),
                    scene);
    const double atTolerance = tolerance + 1e-7 * speed;
    if (std::fabs(std::hypot(hit.normal.x, hit.normal.y) - 1.0) > 1e-4)
        fail(tally, "the normal is not a unit vector", scene);
    if (hit.time > walk.firstHit + 1e-6)
        fail(tally,
             "time of impact " + show(hit.time) + " after the first overlap " + show(walk.firstHit),
             scene);
    const Point normal{hit.normal.x, hit.normal.y};
    if (hit.startedInside)
    {
        if (hit.time != 0.f || depthAt(0, Point{0, 0}) <= -tolerance)
            fail(tally, "startedInside, but not overlapping at time 0", scene);
        // The push-out leaves them exactly touching.
        if (std::fabs(depthAt(0, normal * hit.depth)) > atTolerance)
            fail(tally, "the push-out does not leave them touching", scene);
        return;
    }
    if (depthAt(0, Point{0, 0}) > tolerance)
        fail(tally, "overlapping at time 0 but startedInside is false", scene);
    const double depthThen = depthAt(hit.time, Point{0, 0});
    if (std::fabs(depthThen) > atTolerance)
        fail(tally, "not touching at the time of impact (depth " + show(depthThen) + ")", scene);
    // The normal points out of the target: stepping the mover along it makes the overlap less.
    if (!(depthAt(hit.time, normal * 0.01) < depthThen - 0.005))
        fail(tally, "the normal does not point out of the target", scene);
}

inline Tally sweptCircles(long cases, unsigned seed)
{
    using reference::Point;
    RandomCases random(seed);
    Tally tally;
    for (long i = 0; i < cases && tally.failures < 20; ++i)
    {
        const hitbox::Circle mover{random.position(), random.radius()};
        const hitbox::Circle target{random.position(), random.radius()};
        const hitbox::Vec2 move = random.displacement();
        const bool moving = random.chance(0.3);
        const hitbox::Vec2 targetMove = moving ? random.displacement() : hitbox::Vec2();
        hitbox::Hit hit;
        if (moving)
            hit = hitbox::sweepCircleVsMovingCircle(mover, move, target, targetMove);
        else
            hit = hitbox::sweepCircleVsCircle(mover, move, target);
        // Independent: both centres walk along their own moves.
        const auto depthAt = [&](double s, Point offset)
        {
            const Point moverAt =
                reference::toPoint(mover.center) + reference::toPoint(move) * s + offset;
            const Point targetAt =
                reference::toPoint(target.center) + reference::toPoint(targetMove) * s;
            return reference::circlePenetration(moverAt, mover.radius, targetAt, target.radius);
        };
        const double speed =
            reference::length(reference::toPoint(move) - reference::toPoint(targetMove));
        judgeSweep(tally, hit, depthAt, speed,
                   [&]
                   {
                       return show(mover) + " moving " + show(move) + " vs " + show(target) +
                              " moving " + show(targetMove);
                   });
    }
    return tally;
}

inline Tally sweptCircleVsBox(long cases, unsigned seed)
{
    using reference::Point;
    RandomCases random(seed);
    Tally tally;
    for (long i = 0; i < cases && tally.failures < 20; ++i)
    {
        const hitbox::Circle mover{random.position(), random.radius()};
        const hitbox::Box box = random.box();
        const hitbox::Vec2 move = random.displacement();
        const hitbox::Hit hit = hitbox::sweepCircleVsBox(mover, move, box);
        const auto depthAt = [&](double s, Point offset)
        {
            const Point centre =
                reference::toPoint(mover.center) + reference::toPoint(move) * s + offset;
            return mover.radius - reference::signedDistanceToBox(centre, box);
        };
        judgeSweep(tally, hit, depthAt, reference::length(reference::toPoint(move)),
                   [&] { return show(mover) + " moving " + show(move) + " vs " + show(box); });
    }
    return tally;
}

// The box sweeps of Sweep.h, held to the same brute force.
inline Tally sweptBoxes(long cases, unsigned seed)
{
    using reference::Point;
    RandomCases random(seed);
    Tally tally;
    for (long i = 0; i < cases && tally.failures < 20; ++i)
    {
        hitbox::Box mover = random.box();
        if (random.chance(0.2))
            mover.width = mover.height = 0.f; // a point: segmentVsBox
        const hitbox::Box target = random.box();
        const hitbox::Vec2 move = random.displacement();
        const hitbox::Hit hit =
            mover.width == 0.f
                ? hitbox::segmentVsBox({mover.left, mover.top},
                                       hitbox::Vec2(mover.left, mover.top) + move, target)
                : hitbox::sweepBoxVsBox(mover, move, target);
        const auto depthAt = [&](double s, Point offset)
        { return reference::boxPenetration(mover, reference::toPoint(move) * s + offset, target); };
        judgeSweep(tally, hit, depthAt, reference::length(reference::toPoint(move)),
                   [&] { return show(mover) + " moving " + show(move) + " vs " + show(target); });
    }
    return tally;
}

// ---- polygons: SAT against edge crossings and the Minkowski difference --------------------

inline std::vector<reference::Vec<double>> asVecs(const hitbox::Polygon& polygon)
{
    std::vector<reference::Vec<double>> points;
    for (hitbox::Vec2 p : polygon.points)
        points.push_back({p.x, p.y});
    return points;
}

inline std::vector<reference::Point> asPoints(const hitbox::Polygon& polygon)
{
    std::vector<reference::Point> points;
    for (hitbox::Vec2 p : polygon.points)
        points.push_back({p.x, p.y});
    return points;
}

inline hitbox::Polygon randomConvexPolygon(RandomCases& random, double spread)
{
    if (random.chance(0.3))
        return hitbox::toPolygon(hitbox::OrientedBox{
            {static_cast<float>(random.uniform(0, spread)),
             static_cast<float>(random.uniform(0, spread))},
            {static_cast<float>(random.uniform(1, 60)), static_cast<float>(random.uniform(1, 60))},
            static_cast<float>(random.uniform(0, 360))});
    const double cx = random.uniform(0, spread);
    const double cy = random.uniform(0, spread);
    const double size = random.uniform(5, 80);
    const int count = std::uniform_int_distribution<int>(3, 8)(random.random);
    std::vector<reference::Vec<double>> points;
    for (int k = 0; k < count; ++k)
    {
        const double angle = random.uniform(0, 2.0 * hitbox::piDouble);
        const double r = size * std::sqrt(random.uniform(0, 1));
        points.push_back({static_cast<float>(cx + r * std::cos(angle)),
                          static_cast<float>(cy + r * std::sin(angle))});
    }
    hitbox::Polygon polygon;
    for (auto p : reference::convexHull(points))
        polygon.points.push_back({static_cast<float>(p.x), static_cast<float>(p.y)});
    if (random.chance(0.5))
        std::reverse(polygon.points.begin(), polygon.points.end()); // either winding
    return polygon;
}

inline Tally polygonsWithFractions(long cases, unsigned seed)
{
    RandomCases random(seed);
    Tally tally;
    for (long i = 0; i < cases && tally.failures < 20; ++i)
    {
        const hitbox::Polygon a = randomConvexPolygon(random, 200);
        const hitbox::Polygon b = randomConvexPolygon(random, 200);
        if (a.points.size() < 3 || b.points.size() < 3)
            continue;
        ++tally.cases;
        reference::Point outward{0, 0};
        double runnerUp = 0;
        const double depth = reference::originDepth(
            reference::minkowskiDifference(asVecs(a), asVecs(b)), &outward, &runnerUp);
        if (std::fabs(depth) < tolerance)
        {
            ++tally.ambiguous;
            continue;
        }
        const bool overlap = depth > 0;
        const auto scene = [&] { return show(a) + " vs " + show(b); };
        if (reference::polygonsOverlapByEdges(asPoints(a), asPoints(b)) != overlap)
            fail(tally, "the two references disagree (test bug)", scene);
        const hitbox::Contact contact = hitbox::polygonVsPolygon(a, b);
        const hitbox::AxisReport report = hitbox::findSeparatingAxis(a, b);
        tally.hits += overlap;
        if (contact.hit != overlap || report.separated == overlap)
        {
            fail(tally,
                 std::string("SAT says ") + (contact.hit ? "overlap" : "apart") +
                     ", the references say " + (overlap ? "overlap" : "apart"),
                 scene);
            continue;
        }
        if (hitbox::polygonVsPolygon(b, a).hit != overlap)
            fail(tally, "not symmetric", scene);
        if (!overlap)
        {
            // The reported gap is a real gap no wider than the true distance between them.
            if (report.gap < -1e-4 || report.gap > -depth + tolerance)
                fail(tally, "gap " + show(report.gap) + " vs true distance " + show(-depth), scene);
            continue;
        }
        // The depth is the true minimum translation, and in the true direction when that is
        // unique: the Minkowski difference's nearest edge, seen from A's side.
        if (std::fabs(contact.depth - depth) > tolerance)
            fail(tally,
                 "depth " + show(contact.depth) + " but the minimum translation is " + show(depth),
                 scene);
        if (report.gap != -contact.depth || report.axis != contact.normal)
            fail(tally, "the AxisReport and the Contact disagree", scene);
        if (runnerUp - depth > tolerance &&
            -(contact.normal.x * outward.x + contact.normal.y * outward.y) < 1.0 - 1e-4)
            fail(tally,
                 "normal " + show(contact.normal) + " is not the minimum translation direction",
                 scene);
        if (std::fabs(hitbox::polygonVsPolygon(b, a).depth - contact.depth) > 1e-4)
            fail(tally, "depth not symmetric", scene);
    }
    return tally;
}

// Whole-number corners: shadows and the reference are exact, so touching is decided exactly
// (no ambiguous cases), including polygons with no area (points and segments).
inline Tally polygonsWithWholeNumbers(long cases, unsigned seed)
{
    RandomCases random(seed);
    Tally tally;
    using Whole = reference::Vec<std::int64_t>;
    const auto randomWhole = [&](int low, int high)
    { return std::uniform_int_distribution<int>(low, high)(random.random); };
    for (long i = 0; i < cases && tally.failures < 20; ++i)
    {
        std::vector<Whole> hulls[2];
        hitbox::Polygon polygons[2];
        for (int which = 0; which < 2; ++which)
        {
            std::vector<Whole> points;
            const int count = randomWhole(1, 6);
            for (int k = 0; k < count; ++k)
                points.push_back({randomWhole(0, 8), randomWhole(0, 8)});
            hulls[which] = reference::convexHull(points);
            for (Whole p : hulls[which])
                polygons[which].points.push_back({float(p.x), float(p.y)});
            if (random.chance(0.5))
                std::reverse(polygons[which].points.begin(), polygons[which].points.end());
        }
        ++tally.cases;
        const bool bothFlat = hulls[0].size() < 3 && hulls[1].size() < 3;
        const bool overlap = !bothFlat && reference::originStrictlyInside(
                                              reference::minkowskiDifference(hulls[0], hulls[1]));
        tally.hits += overlap;
        const auto scene = [&] { return show(polygons[0]) + " vs " + show(polygons[1]); };
        const hitbox::Contact contact = hitbox::polygonVsPolygon(polygons[0], polygons[1]);
        if (contact.hit != overlap ||
            hitbox::findSeparatingAxis(polygons[0], polygons[1]).separated == overlap)
        {
            fail(tally,
                 std::string("SAT says ") + (contact.hit ? "overlap" : "apart") +
                     ", the reference says " + (overlap ? "overlap" : "apart"),
                 scene);
            continue;
        }
        // Moving both by the same whole-number offset changes nothing (exact).
        const hitbox::Vec2 offset(float(randomWhole(-1000, 1000)), float(randomWhole(-1000, 1000)));
        hitbox::Polygon movedA = polygons[0];
        hitbox::Polygon movedB = polygons[1];
        for (hitbox::Vec2& p : movedA.points)
            p += offset;
        for (hitbox::Vec2& p : movedB.points)
            p += offset;
        const hitbox::Contact moved = hitbox::polygonVsPolygon(movedA, movedB);
        if (moved.hit != contact.hit ||
            (contact.hit && std::fabs(moved.depth - contact.depth) > 1e-4))
            fail(tally, "moving both shapes changed the answer", scene);
        if (hitbox::polygonVsPolygon(polygons[1], polygons[0]).hit != overlap)
            fail(tally, "not symmetric", scene);
        if (overlap && hulls[0].size() >= 3 && hulls[1].size() >= 3)
        {
            std::vector<reference::Vec<double>> a;
            std::vector<reference::Vec<double>> b;
            for (Whole p : hulls[0])
                a.push_back({double(p.x), double(p.y)});
            for (Whole p : hulls[1])
                b.push_back({double(p.x), double(p.y)});
            const double depth = reference::originDepth(reference::minkowskiDifference(a, b));
            if (std::fabs(contact.depth - depth) > 1e-4)
                fail(tally,
                     "depth " + show(contact.depth) + " but the minimum translation is " +
                         show(depth),
                     scene);
        }
    }
    return tally;
}

// ---- capsules: closest points against four point-to-segment distances ---------------------

inline hitbox::Capsule randomCapsule(RandomCases& random, bool allowZeroRadius)
{
    hitbox::Capsule capsule;
    capsule.start = {random.value(0, 300), random.value(0, 300)};
    capsule.end = random.chance(0.1) ? capsule.start
                                     : capsule.start + hitbox::Vec2(random.value(-150, 150),
                                                                    random.value(-150, 150));
    capsule.radius = allowZeroRadius && random.chance(0.05) ? 0.f : random.value(1, 40);
    return capsule;
}

// Judges one capsule contact against the reference distance between the cores.
template <class DistanceAfterMove, class Scene>
void judgeCapsule(Tally& tally, const hitbox::Contact& contact, double radii, double coreDistance,
                  DistanceAfterMove distanceAfter, const Scene& scene)
{
    ++tally.cases;
    const double margin = radii - coreDistance;
    if (std::fabs(margin) < tolerance)
    {
        ++tally.ambiguous;
        return;
    }
    const bool overlap = margin > 0;
    tally.hits += overlap;
    if (contact.hit != overlap)
        return fail(tally,
                    std::string("says ") + (contact.hit ? "overlap" : "apart") +
                        ", the reference says " + (overlap ? "overlap" : "apart"),
                    scene);
    if (!overlap)
        return;
    if (std::fabs(std::hypot(contact.normal.x, contact.normal.y) - 1.0) > 1e-4)
        fail(tally, "the normal is not a unit vector", scene);
    // Moving A by the contact separates them (touching at most).
    const hitbox::Vec2 push = contact.normal * contact.depth;
    if (radii - distanceAfter(push) > tolerance)
        fail(tally, "moving A by normal * depth leaves them overlapping", scene);
    // With the cores apart, it is also the shortest such move.
    if (coreDistance > tolerance && std::fabs(contact.depth - margin) > tolerance)
        fail(tally,
             "depth " + show(contact.depth) + " but the shortest separating move is " +
                 show(margin),
             scene);
}

inline Tally capsules(long cases, unsigned seed)
{
    using reference::Point;
    using reference::toPoint;
    RandomCases random(seed);
    Tally tally;
    for (long i = 0; i < cases && tally.failures < 20; ++i)
    {
        const hitbox::Capsule a = randomCapsule(random, true);
        const hitbox::Capsule b = randomCapsule(random, true);
        const auto coreDistance = [&](hitbox::Vec2 offset)
        {
            return reference::segmentDistance(toPoint(a.start + offset), toPoint(a.end + offset),
                                              toPoint(b.start), toPoint(b.end));
        };
        judgeCapsule(tally, hitbox::capsuleVsCapsule(a, b), double(a.radius) + b.radius,
                     coreDistance(hitbox::Vec2()), coreDistance,
                     [&] { return show(a) + " vs " + show(b); });
        if (hitbox::capsuleVsCapsule(a, b).hit != hitbox::capsuleVsCapsule(b, a).hit)
            fail(tally, "capsuleVsCapsule is not symmetric",
                 [&] { return show(a) + " vs " + show(b); });

        const hitbox::Circle circle{b.start, b.radius};
        const auto toCircle = [&](hitbox::Vec2 offset)
        {
            return reference::pointSegmentDistance(
                toPoint(circle.center), toPoint(a.start + offset), toPoint(a.end + offset));
        };
        judgeCapsule(tally, hitbox::capsuleVsCircle(a, circle), double(a.radius) + circle.radius,
                     toCircle(hitbox::Vec2()), toCircle,
                     [&] { return show(a) + " vs " + show(circle); });

        hitbox::Capsule round = randomCapsule(random, false);
        const hitbox::Polygon polygon = randomConvexPolygon(random, 300);
        const auto toPolygon = [&](hitbox::Vec2 offset)
        {
            return reference::segmentPolygonDistance(
                toPoint(round.start + offset), toPoint(round.end + offset), asPoints(polygon));
        };
        judgeCapsule(tally, hitbox::capsuleVsPolygon(round, polygon), round.radius,
                     toPolygon(hitbox::Vec2()), toPolygon,
                     [&] { return show(round) + " vs " + show(polygon); });
    }
    return tally;
}

// What every agreement test asserts about a tally.
inline void expectAgreement(const Tally& tally, long expectedCases)
{
    EXPECT_EQ(tally.failures, 0);
    EXPECT_GE(tally.cases, expectedCases * 9 / 10);
    // Near-touching cases that cannot be judged stay rare (well under 2%).
    EXPECT_LT(tally.ambiguous * 50, tally.cases) << tally.ambiguous << " ambiguous cases";
    // Both answers really occur.
    EXPECT_GT(tally.hits * 20, tally.cases) << "too few hits to mean anything";
    EXPECT_LT(tally.hits * 20, tally.cases * 19) << "too few misses to mean anything";
    std::cout << "[ agreement ] " << tally.cases << " cases, " << tally.hits << " hits, "
              << tally.ambiguous << " not judged (within " << tolerance << " px of touching)\n";
}

} // namespace agreement
