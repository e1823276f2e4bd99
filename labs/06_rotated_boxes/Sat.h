// Sat.h - the separating axis theorem, written out step by step (tasks 1 and 2).
//
// Two convex shapes are apart exactly when some straight line fits between them. For
// polygons it is enough to try the lines at right angles to their edges: project (cast the
// "shadow" of) both shapes onto each edge's normal; if the shadows do not overlap on one of
// those axes, a line fits there. If they overlap on every axis, the axis where they overlap
// least is the shortest way out: the minimum translation vector (Ericson, Real-Time
// Collision Detection, 4.4).
// The framework's hitbox::polygonVsPolygon (Polygon.h) does the same; the tests compare.
#pragma once

#include "hitbox/geometry/Polygon.h"

#include <vector>

// A polygon's shadow on an axis: the smallest and largest of dot(point, axis).
struct Shadow
{
    float min = 0.f;
    float max = 0.f;
};

// The answer of the separating axis test.
struct SatResult
{
    bool separated = true; // false: the shapes share area
    // Separated: the axis with the LARGEST gap. Overlapping: the axis of LEAST overlap,
    // pointing the way A must move to get out of B (so axis * depth is the MTV).
    hitbox::Vec2 axis;
    float gap = 0.f; // separated: the gap in pixels (>= 0); overlapping: -depth (< 0)

    float depth() const { return separated ? 0.f : -gap; }
};

// One axis to try, with both polygons' shadows on it.
struct AxisShadows
{
    hitbox::Vec2 axis; // unit length
    Shadow a;          // A's shadow on it
    Shadow b;          // B's shadow on it
};

// Task 1: the shadow of `polygon` on the unit vector `axis`.
Shadow projectOnto(const hitbox::Polygon& polygon, hitbox::Vec2 axis);

// Task 2: the answer of the separating axis test, from the shadows of A and B on every axis
// to try (never empty). Shadows that only touch (gap 0) count as separated: touching is not
// a collision.
SatResult chooseAxis(const std::vector<AxisShadows>& axes);

// The separating axis test for two convex polygons (A = first, B = second): casts both
// shadows (task 1) on the normal of every edge of both, and lets chooseAxis (task 2) decide.
SatResult separatingAxisTest(const hitbox::Polygon& a, const hitbox::Polygon& b);
