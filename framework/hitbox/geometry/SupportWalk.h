// SupportWalk.h - the furthest corner of a convex polygon along a direction, found by walking.
// Shared by the polygon tests (Polygon.cpp) and capsule against polygon (Capsule.cpp).
// Range: its callers' (Polygon.h, Capsule.h: corners within +-exactRange, Range.h).
#pragma once

#include "hitbox/geometry/Vec2.h"

#include <cstddef>
#include <vector>

namespace hitbox
{

// a.x * b.x + a.y * b.y in double. A float times a float is exact in double, so the shadows
// of whole-number corners are exact (touching is found exactly) and tiny values keep their
// digits.
[[nodiscard]] inline double dotExact(Vec2 a, Vec2 b)
{
    return double(a.x) * b.x + double(a.y) * b.y;
}

// THE TRICK "walking support points" (Ericson, Real-Time Collision Detection, 9.5.4 and
// 9.5.5: hill-climbing for extreme vertices, starting from the last answer). Along a convex
// polygon the shadow of the corners rises to one peak and falls again, so the furthest corner
// is found by stepping to a neighbour that reaches further until none does (on a polygon
// with a dent it could stop at the wrong peak: cleaned() gives the hull). The separating
// axes come in order round a polygon, so each climb starts next to its answer: a whole test
// costs O(n + m) steps instead of projecting every corner on every axis, O((n + m)^2).
struct SupportWalk
{
    const std::vector<Vec2>& points;
    std::size_t at = 0; // where the last climb ended

    // The largest dotExact(corner, direction) over the polygon's corners.
    [[nodiscard]] double furthestAlong(Vec2 direction)
    {
        const std::size_t count = points.size();
        double best = dotExact(points[at], direction);
        for (;;)
        {
            const std::size_t next = (at + 1) % count;
            const std::size_t previous = (at + count - 1) % count;
            if (dotExact(points[next], direction) > best)
                at = next;
            else if (dotExact(points[previous], direction) > best)
                at = previous;
            else
                return best;
            best = dotExact(points[at], direction);
        }
    }
};

} // namespace hitbox
