// Polygon.h - rotated boxes and convex polygons, tested by the separating axis theorem.
//
// An axis-aligned test (Overlap.h) is only right while nothing rotates. For a rotated box,
// or any convex polygon, the separating axis theorem (Ericson, Real-Time Collision
// Detection, 5.2.1) decides: two convex shapes are apart exactly when some line separates them, and
// it is enough to try the lines at right angles to each edge. Project both shapes onto each
// such axis; if the two shadows do not overlap on one axis, the shapes are apart. If they
// overlap on every axis, the axis with the smallest overlap gives the minimum translation.
//
// Units: pixels; angles in degrees, clockwise on screen (y down), as sf::Transformable uses.
//
// EDGE RULES (the "share area" rule of Overlap.h):
//   - Shapes collide only when they share area: shadows that only touch (overlap 0) on some
//     axis mean apart. Touching edges and corners do not collide.
//   - Either winding (clockwise or anticlockwise) works, and the points may come in any
//     order: every test works on the polygon's convex hull (a concave polygon, or one made
//     slightly concave by rounding, is tested as its hull).
//   - Degenerate polygons: repeated points are ignored. A polygon with no area (one point,
//     or all points on a line) is a point or a segment: it collides when it reaches strictly
//     inside the other polygon. Two polygons with no area never collide (nothing to share;
//     note boxVsBox differs for two crossing zero-size boxes). An empty polygon never
//     collides.
//   - Range (Range.h): every coordinate and half size within +-exactRange (1e6 px), where
//     the answers are exact up to float rounding. Outside it, and for NaN, infinity or a NaN
//     angle: never collide. A hit always has a depth > 0 (penetrates(), Shapes.h), a finite
//     point and a unit normal.
//   - Cost: O(n log n + m log m) for polygons of n and m corners: the hull, then a walk of
//     O(n + m) steps (walking support points, Polygon.cpp).
//   - Ties: among axes with the same overlap, the more horizontal axis wins (so the x axis,
//     as in boxVsBoxContact), then the first tried (A's hull edges from its leftmost corner, then
//     B's). On one axis, equal pushes either way go to the negative direction (left, up). So two
//     axis-aligned boxes get boxVsBoxContact's normal, and its depth up to the last bit of
//     rounding (exactly its depth when the coordinates are whole numbers).
//   - Contact normal: out of B towards A (Shapes.h), unit length; depth in pixels.
//     Contact point: the vertex that reaches deepest, moved onto B's surface (approximate for
//     edge-to-edge contact: one point of the touching stretch, not its middle).
#pragma once

#include "hitbox/geometry/Range.h"
#include "hitbox/geometry/Shapes.h"

#include <vector>

namespace hitbox
{

// A box rotated about its centre. halfSize is half the width and half the height before
// rotating; angleDegrees turns it clockwise on screen, like sf::Transformable::setRotation.
struct OrientedBox
{
    Vec2 center;
    Vec2 halfSize;
    float angleDegrees = 0.f;
};

// A convex polygon: its corners in order around the edge (either way round). World pixels.
struct Polygon
{
    std::vector<Vec2> points;
};

// The four corners, starting with the box's own top-left and going down its left side first
// (so the first edge's axis is the box's x axis). A negative half size is read as positive.
[[nodiscard]] Polygon toPolygon(const OrientedBox& box);
// The four corners of an axis-aligned box, in the same order (negative sizes normalised).
[[nodiscard]] Polygon toPolygon(const Box& box);

// The polygon every test here works on: the corners of its convex hull, from the leftmost
// (then topmost) corner, clockwise on screen. Empty when a point is NaN or out of range.
[[nodiscard]] Polygon convexHull(const Polygon& polygon);

// Twice the signed area (positive when the points run clockwise on screen, y down).
[[nodiscard]] float twiceSignedArea(const Polygon& polygon);

// What the search for a separating axis found, for drawing: when separated, the axis with
// the LARGEST gap (the clearest view of the separation) and that gap in pixels (>= 0; 0 when
// touching); otherwise the axis of LEAST overlap, with gap = -depth. `axis` is a unit vector
// pointing from B's side towards A's side. Nothing to test (an empty polygon, NaN, two points)
// gives separated == true, axis (0, 0), gap 0.
struct AxisReport
{
    bool separated = true;
    Vec2 axis;
    float gap = 0.f;
};
[[nodiscard]] AxisReport findSeparatingAxis(const Polygon& a, const Polygon& b);

// The separating axis theorem with the minimum translation: moving A by normal * depth
// leaves the two exactly touching. Corners within +-exactRange, else no hit.
[[nodiscard]] Contact polygonVsPolygon(const Polygon& a, const Polygon& b);
// polygonVsPolygon on the two boxes' corners (so every corner within +-exactRange).
[[nodiscard]] Contact orientedBoxVsOrientedBox(const OrientedBox& a, const OrientedBox& b);

// A = the circle, B = the polygon: the normal points out of the polygon towards the circle
// (swap the normal's sign to see it from the polygon). The centre's closest point on the
// polygon decides; a centre inside leaves through the nearest edge. Zero radius: a point,
// a hit only when its way out is > 0 (strictly inside). A polygon with no area collides
// when it reaches strictly inside the circle. Centre, radius, corners within +-exactRange.
[[nodiscard]] Contact circleVsPolygon(const Circle& circle, const Polygon& polygon);

// True when `point` is strictly inside the convex polygon (on an edge is outside). Point
// and corners within +-exactRange, else false.
[[nodiscard]] bool pointInPolygon(Vec2 point, const Polygon& polygon);

} // namespace hitbox
