// Capsule.h - capsules: a segment with a radius (Ericson, Real-Time Collision
// Detection, 4.5: sphere-swept volumes).
//
// A capsule is every point within `radius` of the segment from `start` to `end`: a good
// shape for a character or a sword swing. Every capsule test comes down to one question:
// how close do the two "cores" (segments, points) get? Closer than the radii added = overlap.
//
// Units: pixels. The normal convention is the one of Shapes.h: out of B towards A, where A
// is the first argument.
//
// EDGE RULES (the "share area" rule of Overlap.h):
//   - Collide only when the distance between the cores is strictly less than the radii
//     added (exactly touching is not a collision).
//   - Zero radius: the capsule is a segment (or a point when start == end); it collides when
//     it reaches strictly inside the other shape. Two shapes with no area never collide.
//   - Zero-length capsule (start == end): a circle.
//   - Range (Range.h): every coordinate and radius within +-exactRange (1e6 px), where the
//     answers are exact up to float rounding. Outside it, negative radius, NaN or infinity:
//     never collide. A hit always has a depth > 0 (penetrates(), Shapes.h) and a unit normal.
//   - When the cores touch or cross (distance 0, or within rounding: a millionth of the
//     coordinates' size), there is no single closest direction. The
//     normal is then at right angles to B's segment (to A's segment if B's is a point), on
//     the side of A's middle; the depth moves A far enough along it to clear B. It is a
//     separating move, not always the shortest one. Fully degenerate (both points at the same
//     place): normal (-1, 0), as circleVsCircleContact.
#pragma once

#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

struct Capsule
{
    Vec2 start;
    Vec2 end;
    float radius = 0.f;
};

// The point of the segment start..end nearest to `point` (start when the segment has no
// length). Ties cannot happen: the nearest point of a segment is unique.
[[nodiscard]] Vec2 closestPointOnSegment(Vec2 point, Vec2 start, Vec2 end);

// The closest pair of points between two segments (first on segment 1, second on 2). For
// parallel overlapping segments, where many pairs are equally close, one of them.
struct SegmentPoints
{
    Vec2 first;
    Vec2 second;
};
[[nodiscard]] SegmentPoints closestPointsOfSegments(Vec2 start1, Vec2 end1, Vec2 start2, Vec2 end2);

// A = the capsule, B = the circle. Point: on the circle's rim.
[[nodiscard]] Contact capsuleVsCircle(const Capsule& capsule, const Circle& circle);
// Point: on B's surface, facing A.
[[nodiscard]] Contact capsuleVsCapsule(const Capsule& a, const Capsule& b);
// A = the capsule, B = the polygon's convex hull (Polygon.h's rules for degenerate polygons).
// Separating axes: the polygon's edge normals, the capsule's own normal, and from each end of
// the capsule to the corner nearest it (the round ends need those). O(n) in the corners.
[[nodiscard]] Contact capsuleVsPolygon(const Capsule& capsule, const Polygon& polygon);

} // namespace hitbox
