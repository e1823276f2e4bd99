#include "hitbox/geometry/Resolve.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Response.h"
#include "hitbox/geometry/Vec2.h"

#include <algorithm>
#include <cmath>

namespace hitbox
{
namespace
{

constexpr int maxRounds = 3;

Box movedBy(Box box, Vec2 offset)
{
    box.left += offset.x;
    box.top += offset.y;
    return box;
}

// The velocity to keep after touching a surface: the part into it goes entirely.
Vec2 withoutPartInto(Vec2 velocity, Vec2 normal)
{
    const float into = dot(velocity, normal);
    return into < 0.f ? velocity - normal * into : velocity;
}

// `start` such that start + size ends exactly at `edge` or before it (float rounding can
// put start + size one step past the edge, which would count as an overlap).
float startEndingAt(float edge, float size)
{
    float start = edge - size;
    while (start + size > edge)
        start = std::nextafter(start, -INFINITY);
    return start;
}

// Moves `box` out of `solid` through the face with normal `normal` (an axis direction).
Box placedAgainst(Box box, const Box& solid, Vec2 normal)
{
    if (normal.x < 0.f)
        box.left = startEndingAt(solid.left, box.width);
    else if (normal.x > 0.f)
        box.left = rightOf(solid);
    else if (normal.y < 0.f)
        box.top = startEndingAt(solid.top, box.height);
    else if (normal.y > 0.f)
        box.top = bottomOf(solid);
    return box;
}

struct Candidate
{
    std::size_t solid;
    float time;
    float sharedLength; // how much of the face they touch along at that time (0 for a corner)
};

// How long the stretch of surface is along which the moved mover touches the solid.
float sharedLengthOf(const Hit& hit, const Box& mover, Vec2 move, const Box& solid)
{
    const Box then(mover.left + move.x * hit.time, mover.top + move.y * hit.time, mover.width,
                   mover.height);
    if (hit.normal.x != 0.f)
        return std::fmin(bottomOf(then), bottomOf(solid)) - std::fmax(then.top, solid.top);
    return std::fmin(rightOf(then), rightOf(solid)) - std::fmax(then.left, solid.left);
}

} // namespace

MoveResult moveBoxAndSlide(const Box& box, Vec2 velocity, float dt, const std::vector<Box>& solids,
                           bool sortByTime)
{
    MoveResult result{normalised(box), velocity, {}};
    if (!isFinite(box) || !isFinite(velocity) || !std::isfinite(dt) || !(dt > 0.f))
        return result;
    // The stated range (Range.h): outside it a sum can overflow to infinity (3e38 px/s once
    // ended at (inf, inf)), so the box stays where it is.
    const Vec2 wholeMove{velocity.x * dt, velocity.y * dt};
    if (!withinExactRange(Vec2{result.box.left, result.box.top}) ||
        !withinExactRange(Vec2{result.box.width, result.box.height}) ||
        !withinExactRange(wholeMove))
        return result;
    Vec2 stepVelocity = velocity;            // used for this step's move
    float stepLeft = 1.f;                    // the fraction of the step not yet moved
    std::vector<Candidate> resolved;         // for the rounding clean-up at the end
    std::vector<Box> placements{result.box}; // where the box has been: the fallback at the end
    for (int round = 0; round < maxRounds; ++round)
    {
        // 1. Which solids would this move hit, and when?
        std::vector<Candidate> candidates;
        for (std::size_t i = 0; i < solids.size(); ++i)
        {
            const Vec2 move = stepVelocity * (dt * stepLeft);
            const Hit hit = sweepBoxVsBox(result.box, move, solids[i]);
            if (hit.hit)
                candidates.push_back(
                    {i, hit.time, sharedLengthOf(hit, result.box, move, normalised(solids[i]))});
        }
        if (candidates.empty())
            break;
        // [slide:resolve-time-order]
        // 2. Nearest first (javidx9's sort by time): the floor under the box
        //    (t = 0) is resolved before the next tile's corner, so the seam
        //    between tiles never stops the box. At the same time, a face
        //    touched along its length goes before a corner.
        if (sortByTime)
            std::stable_sort(candidates.begin(), candidates.end(),
                             [](const Candidate& a, const Candidate& b) {
                                 return a.time < b.time ||
                                        (a.time == b.time && a.sharedLength > b.sharedLength);
                             });
        // 3. Resolve in that order. Each hit moves the box to where it touches that solid
        //    and spends that part of the step; the rest of the step goes on from there with
        //    the slid velocity (sweeping the rest from the start again would cut across
        //    corners the box never reaches).
        for (const Candidate& candidate : candidates)
        {
            const Box solid = normalised(solids[candidate.solid]);
            const Vec2 move = stepVelocity * (dt * stepLeft);
            const Hit hit = sweepBoxVsBox(result.box, move, solid);
            if (!hit.hit)
                continue; // an earlier slide already took this one away
            result.box = placedAgainst(movedBy(result.box, move * hit.time), solid, hit.normal);
            placements.push_back(result.box);
            stepLeft *= 1.f - hit.time;
            stepVelocity = withoutPartInto(stepVelocity, hit.normal);
            result.velocity = withoutPartInto(result.velocity, hit.normal);
            result.hits.push_back(hit);
            resolved.push_back(candidate);
        }
        // [/slide]
    }
    // What is left of the step after the last round: stop at the first solid it would meet
    // (more surfaces than rounds, e.g. a box wedged between three tiles and a fourth), so the
    // box never ends inside one it was not swept against.
    const Vec2 rest = stepVelocity * (dt * stepLeft);
    Hit first;
    std::size_t firstSolid = solids.size();
    for (std::size_t i = 0; i < solids.size(); ++i)
    {
        const Hit hit = sweepBoxVsBox(result.box, rest, normalised(solids[i]));
        if (hit.hit && (!first.hit || hit.time < first.time))
        {
            first = hit;
            firstSolid = i;
        }
    }
    if (first.hit)
    {
        const Box solid = normalised(solids[firstSolid]);
        result.box = placedAgainst(movedBy(result.box, rest * first.time), solid, first.normal);
        result.velocity = withoutPartInto(result.velocity, first.normal);
        result.hits.push_back(first);
        resolved.push_back({firstSolid, first.time, 0.f});
    }
    else
        result.box = movedBy(result.box, rest);
    // Float rounding can leave the box a hair inside a surface it slid to; put it exactly
    // against that surface, so that touching stays touching (the edge rule).
    for (std::size_t i = 0; i < resolved.size(); ++i)
    {
        const Box solid = normalised(solids[resolved[i].solid]);
        if (boxVsBox(result.box, solid))
            result.box = placedAgainst(result.box, solid, result.hits[i].normal);
    }
    // A gap narrower than the box (two solids pushing it back and forth): no place on the path
    // is against both, so the box stops at the last place it reached that overlaps nothing.
    const auto overlapsASolid = [&solids](const Box& where)
    {
        return std::any_of(solids.begin(), solids.end(),
                           [&where](const Box& solid)
                           { return boxVsBox(where, normalised(solid)); });
    };
    if (overlapsASolid(result.box))
        for (auto place = placements.rbegin(); place != placements.rend(); ++place)
            if (!overlapsASolid(*place))
            {
                result.box = *place;
                result.velocity = {0.f, 0.f};
                break;
            }
    return result;
}

} // namespace hitbox
