#include "hitbox/geometry/Explain.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Sweep.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace hitbox
{
namespace
{

// Numbers as a person writes them: 10, 12.5, 0.333333 (six significant digits), nan, inf.
std::string number(double value)
{
    std::ostringstream text;
    text.precision(6);
    text << value;
    return text.str();
}

// The verdict's reason for a circle beyond Range.h's range (circleVsCircle and circleVsBox
// answer "no hit" there).
std::string outsideTheRange()
{
    return "a circle beyond +-" + number(exactRange) +
           " px (the exact range, Range.h) never collides";
}

std::string point(Vec2 value)
{
    return "(" + number(value.x) + ", " + number(value.y) + ")";
}

std::string span(float low, float high)
{
    return "[" + number(low) + ", " + number(high) + "]";
}

enum class SpanRelation
{
    Overlap,
    Touch,
    Apart
};

// The edge rule of Shapes.h (spansOverlap), and what it saw.
SpanRelation relate(float minA, float maxA, float minB, float maxB)
{
    if (spansOverlap(minA, maxA, minB, maxB))
        return SpanRelation::Overlap;
    if (maxA == minB || maxB == minA)
        return SpanRelation::Touch;
    return SpanRelation::Apart;
}

// "A [10, 30] and B [30, 50] only touch - touching is not a collision", and the like.
std::string spanLine(const std::string& label, const std::string& nameA, float minA, float maxA,
                     const std::string& nameB, float minB, float maxB)
{
    std::string line =
        label + ": " + nameA + " " + span(minA, maxA) + " and " + nameB + " " + span(minB, maxB);
    switch (relate(minA, maxA, minB, maxB))
    {
    case SpanRelation::Overlap:
        return line + " overlap by " +
               number(double(std::fmin(maxA, maxB)) - double(std::fmax(minA, minB)));
    case SpanRelation::Touch:
        return line + " only touch \xE2\x80\x94 touching is not a collision";
    case SpanRelation::Apart:
        break;
    }
    const double gap = minB > maxA ? double(minB) - maxA : double(minA) - maxB;
    return line + " are " + number(gap) + " apart";
}

// "less than", "equal to" or "more than", comparing two squared lengths.
std::string compare(float left, float right)
{
    if (left < right)
        return " < ";
    if (left == right)
        return " = ";
    return " > ";
}

} // namespace

std::string toText(const Explanation& explanation)
{
    std::string text = explanation.verdict;
    for (const std::string& step : explanation.steps)
        text += "\n  " + step;
    return text;
}

Explanation explainBoxes(const Box& first, const Box& second, const std::string& nameA,
                         const std::string& nameB)
{
    Explanation why;
    why.collides = boxVsBox(first, second);
    const std::string pair = nameA + " and " + nameB;
    if (!isFinite(first) || !isFinite(second))
    {
        why.verdict = pair + " do not collide: a box with NaN or infinity in it never collides";
        return why;
    }
    const Box a = normalised(first);
    const Box b = normalised(second);
    why.steps.push_back(spanLine("x", nameA, a.left, rightOf(a), nameB, b.left, rightOf(b)));
    why.steps.push_back(spanLine("y", nameA, a.top, bottomOf(a), nameB, b.top, bottomOf(b)));
    if (why.collides)
    {
        why.verdict = pair + " collide: they overlap on x and on y";
        return why;
    }
    const SpanRelation x = relate(a.left, rightOf(a), b.left, rightOf(b));
    const bool xDecides = x != SpanRelation::Overlap;
    const SpanRelation decider = xDecides ? x : relate(a.top, bottomOf(a), b.top, bottomOf(b));
    why.verdict = pair + " do not collide: on " + (xDecides ? "x" : "y") + " they " +
                  (decider == SpanRelation::Touch ? "only touch" : "are apart");
    return why;
}

Explanation explainCircles(const Circle& a, const Circle& b, const std::string& nameA,
                           const std::string& nameB)
{
    Explanation why;
    why.collides = circleVsCircle(a, b);
    const std::string pair = nameA + " and " + nameB;
    if (!isFinite(a) || !isFinite(b) || a.radius < 0.f || b.radius < 0.f)
    {
        why.verdict = pair + " do not collide: a circle with NaN, infinity or a negative radius "
                             "never collides";
        return why;
    }
    if (!withinExactRange(a.center) || !withinExactRange(a.radius) || !withinExactRange(b.center) ||
        !withinExactRange(b.radius))
    {
        why.verdict = pair + " do not collide: " + outsideTheRange();
        return why;
    }
    // The same float sums as circleVsCircle, so the comparison shown is the one it made.
    const Vec2 between = a.center - b.center;
    const float distanceSquared = between.x * between.x + between.y * between.y;
    const float radiusSum = a.radius + b.radius;
    const float reachSquared = radiusSum * radiusSum;
    why.steps.push_back("centres " + point(a.center) + " and " + point(b.center) +
                        ": squared distance " + number(between.x) + "\xC2\xB2 + " +
                        number(between.y) + "\xC2\xB2 = " + number(distanceSquared));
    why.steps.push_back("radius sum " + number(a.radius) + " + " + number(b.radius) + " = " +
                        number(radiusSum) + ", squared " + number(reachSquared));
    const std::string comparison =
        number(distanceSquared) + compare(distanceSquared, reachSquared) + number(reachSquared);
    if (why.collides)
    {
        why.steps.push_back(comparison + ": the centres are closer than the radii reach");
        why.verdict = pair + " collide: squared distance " + comparison;
    }
    else if (distanceSquared == reachSquared)
    {
        why.steps.push_back(comparison +
                            ": they only touch \xE2\x80\x94 touching is not a collision");
        why.verdict = pair + " do not collide: they only touch (" + comparison + ")";
    }
    else
    {
        why.steps.push_back(comparison + ": the centres are further apart than the radii reach");
        why.verdict = pair + " do not collide: squared distance " + comparison;
    }
    return why;
}

Explanation explainCircleBox(const Circle& circle, const Box& box, const std::string& nameA,
                             const std::string& nameB)
{
    Explanation why;
    why.collides = circleVsBox(circle, box);
    const std::string pair = nameA + " and " + nameB;
    if (!isFinite(circle) || circle.radius < 0.f || !isFinite(box))
    {
        why.verdict = pair + " do not collide: NaN, infinity or a negative radius never collides";
        return why;
    }
    if (!withinExactRange(circle.center) || !withinExactRange(circle.radius))
    {
        why.verdict = pair + " do not collide: " + outsideTheRange();
        return why;
    }
    const Box b = normalised(box);
    if (pointInBox(circle.center, b))
    {
        why.steps.push_back(nameA + "'s centre " + point(circle.center) + " is inside " + nameB +
                            " (x " + span(b.left, rightOf(b)) + ", y " + span(b.top, bottomOf(b)) +
                            ")");
        why.verdict = pair + " collide: the circle's centre is inside the box";
        return why;
    }
    // The same nearest point and float sums as circleVsBox.
    const Vec2 nearest(std::fmin(std::fmax(circle.center.x, b.left), rightOf(b)),
                       std::fmin(std::fmax(circle.center.y, b.top), bottomOf(b)));
    const Vec2 fromBox = circle.center - nearest;
    const float distanceSquared = fromBox.x * fromBox.x + fromBox.y * fromBox.y;
    const float radiusSquared = circle.radius * circle.radius;
    why.steps.push_back(nameB + "'s point nearest " + nameA + "'s centre " + point(circle.center) +
                        " is " + point(nearest));
    why.steps.push_back("squared distance " + number(distanceSquared) + ", squared radius " +
                        number(circle.radius) + "\xC2\xB2 = " + number(radiusSquared));
    const std::string comparison =
        number(distanceSquared) + compare(distanceSquared, radiusSquared) + number(radiusSquared);
    if (why.collides)
        why.verdict = pair + " collide: squared distance " + comparison;
    else if (distanceSquared == radiusSquared)
        why.verdict = pair + " do not collide: they only touch (" + comparison +
                      ") \xE2\x80\x94 touching is not a collision";
    else
        why.verdict = pair + " do not collide: squared distance " + comparison;
    return why;
}

Explanation explainPolygons(const Polygon& first, const Polygon& second, const std::string& nameA,
                            const std::string& nameB)
{
    Explanation why;
    why.collides = polygonVsPolygon(first, second).hit;
    const std::string pair = nameA + " and " + nameB;
    const Polygon a = convexHull(first);
    const Polygon b = convexHull(second);
    if (a.points.empty() || b.points.empty())
    {
        why.verdict = pair + " do not collide: a polygon with no corners (or NaN, or out of "
                             "range) never collides";
        return why;
    }
    std::string separating;
    for (int side = 0; side < 2; ++side)
    {
        const Polygon& owner = side == 0 ? a : b;
        const std::string& ownerName = side == 0 ? nameA : nameB;
        const std::size_t count = owner.points.size();
        for (std::size_t i = 0; i < count && count > 1; ++i)
        {
            const Vec2 edge = owner.points[(i + 1) % count] - owner.points[i];
            const Vec2 axis = unitVectorOr(perpendicular(edge), Vec2(0.f, 0.f));
            if (axis == Vec2(0.f, 0.f))
                continue;
            float minA = std::numeric_limits<float>::infinity(), maxA = -minA;
            float minB = minA, maxB = -minA;
            for (Vec2 corner : a.points)
            {
                minA = std::fmin(minA, dot(corner, axis));
                maxA = std::fmax(maxA, dot(corner, axis));
            }
            for (Vec2 corner : b.points)
            {
                minB = std::fmin(minB, dot(corner, axis));
                maxB = std::fmax(maxB, dot(corner, axis));
            }
            const std::string label = "axis " + point(axis) + " (edge " + std::to_string(i + 1) +
                                      " of " + ownerName + ")";
            std::string line =
                spanLine(label, nameA + "'s shadow", minA, maxA, nameB + "'s shadow", minB, maxB);
            if (relate(minA, maxA, minB, maxB) != SpanRelation::Overlap)
            {
                line += ": this axis separates them";
                if (separating.empty())
                    separating = label;
            }
            why.steps.push_back(line);
        }
    }
    if (why.collides)
        why.verdict = pair + " collide: their shadows overlap on every one of the " +
                      std::to_string(why.steps.size()) + " axes";
    else if (!separating.empty())
        why.verdict = pair + " do not collide: " + separating + " separates them";
    else
        why.verdict = pair + " do not collide: the overlap is too thin to have any area";
    return why;
}

namespace
{

struct AxisTimes
{
    double enter;
    double exit;
};

// When, as a fraction of the move, the mover's span starts and stops overlapping the
// target's (Ericson, Real-Time Collision Detection, 5.5.8: moving AABBs).
AxisTimes axisTimes(float minA, float maxA, float minB, float maxB, float move)
{
    const double infinity = std::numeric_limits<double>::infinity();
    if (move == 0.f)
        return spansOverlap(minA, maxA, minB, maxB) ? AxisTimes{-infinity, infinity}
                                                    : AxisTimes{infinity, -infinity};
    if (move > 0.f)
        return {(double(minB) - maxA) / move, (double(maxB) - minA) / move};
    return {(double(maxB) - minA) / move, (double(minB) - maxA) / move};
}

std::string timesLine(const std::string& label, const std::string& nameA, float minA, float maxA,
                      float move, const std::string& nameB, float minB, float maxB)
{
    const AxisTimes times = axisTimes(minA, maxA, minB, maxB, move);
    std::string line = label + ": " + nameA + " " + span(minA, maxA) + " moving " +
                       (move >= 0.f ? "+" : "") + number(move) + " against " + nameB + " " +
                       span(minB, maxB);
    if (move == 0.f)
        return line + (times.enter < times.exit ? ": not moving, always overlapping on " + label
                                                : ": not moving, never overlapping on " + label);
    return line + ": overlaps from t = " + number(times.enter) + " to t = " + number(times.exit);
}

} // namespace

Explanation explainSweep(const Box& moverBox, Vec2 displacement, const Box& targetBox,
                         const std::string& nameA, const std::string& nameB)
{
    Explanation why;
    const Hit hit = sweepBoxVsBox(moverBox, displacement, targetBox);
    why.collides = hit.hit;
    const std::string pair = nameA + " and " + nameB;
    if (!isFinite(moverBox) || !isFinite(targetBox) || !isFinite(displacement))
    {
        why.verdict = nameA + " misses " + nameB + ": NaN or infinity never hits";
        return why;
    }
    const Box a = normalised(moverBox);
    const Box b = normalised(targetBox);
    if (hit.startedInside)
    {
        why.steps.push_back(toText(explainBoxes(a, b, nameA, nameB)));
        why.verdict = nameA + " hits " + nameB + " at t = 0: they already overlap at the start";
        return why;
    }
    why.steps.push_back(
        timesLine("x", nameA, a.left, rightOf(a), displacement.x, nameB, b.left, rightOf(b)));
    why.steps.push_back(
        timesLine("y", nameA, a.top, bottomOf(a), displacement.y, nameB, b.top, bottomOf(b)));
    const AxisTimes x = axisTimes(a.left, rightOf(a), b.left, rightOf(b), displacement.x);
    const AxisTimes y = axisTimes(a.top, bottomOf(a), b.top, bottomOf(b), displacement.y);
    const double enter = std::fmax(x.enter, y.enter);
    const double exit = std::fmin(x.exit, y.exit);
    why.steps.push_back("both axes overlap from t = " + number(enter) +
                        " (the later start) to t = " + number(exit) +
                        " (the earlier end); the move is t = 0 to 1");
    if (hit.hit)
        why.verdict = nameA + " hits " + nameB + " at t = " + number(hit.time) + ", on its " +
                      (hit.normal.x != 0.f ? "x" : "y") + " side";
    else if (!(enter < exit))
        why.verdict = nameA + " misses " + nameB +
                      ": the stretches when x and when y overlap never meet (touching is not a "
                      "collision)";
    else if (enter >= 1.)
        why.verdict = nameA + " misses " + nameB + ": they would meet at t = " + number(enter) +
                      ", after the move ends";
    else
        why.verdict = nameA + " misses " + nameB + ": they overlapped only before the move";
    return why;
}

} // namespace hitbox
