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

// Task 1: the shadow of `polygon` on the unit vector `axis`.
Shadow projectOnto(const hitbox::Polygon& polygon, hitbox::Vec2 axis);

// Task 2: the separating axis test for two convex polygons (A = first, B = second).
// Shadows that only touch (gap 0) count as separated: touching is not a collision.
SatResult separatingAxisTest(const hitbox::Polygon& a, const hitbox::Polygon& b);
