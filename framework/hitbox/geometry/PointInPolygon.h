// PointInPolygon.h - is a point inside a polygon that may be concave? The crossing-number test.
//
// Send a ray from the point to the right (+x) and count the edges it crosses: an odd count
// means inside (Jordan curve theorem). Each edge counts when its ends lie on different sides
// of the ray's line, with the half-open rule "one end strictly below, the other not", so a
// ray through a corner counts that corner once (Haines, "Point in Polygon Strategies",
// Graphics Gems IV, 1994; O'Rourke, Computational Geometry in C, 2nd ed., 7.4; Ericson,
// Real-Time Collision Detection, 5.4.1). Unlike the separating axis test of Polygon.h, it works
// on concave polygons as they are, not on their hull. Units: pixels, y down.
#pragma once

#include "hitbox/geometry/Polygon.h"

namespace hitbox
{

// What the crossing-number test found.
struct PointInPolygonResult
{
    bool inside = false; // strictly inside (even-odd rule); never when onEdge
    bool onEdge = false; // exactly on an edge or a corner: touching, so not inside
    int crossings = 0;   // edges the ray from the point to +x crossed; odd when inside
};

// Is `point` strictly inside `polygon` (corners in order around the edge, either way round,
// concave allowed)? EDGE RULE: a point on an edge or a corner is not inside (onEdge; touching
// is not colliding, as pointInBox). Self-crossing polygons use the even-odd rule. Repeated
// corners are ignored; fewer than 3 corners or zero area (all on one line): never inside
// (onEdge still says whether the point lies on it). NaN, infinity or any coordinate outside
// +-exactRange (Range.h), in the point or a corner: not inside, not on an edge, 0 crossings.
[[nodiscard]] PointInPolygonResult pointInPolygon(const Polygon& polygon, Vec2 point);

} // namespace hitbox
