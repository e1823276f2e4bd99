// SweptCircle.h - where along a move does a circle first hit a circle or a box?
//
// The circle versions of Sweep.h, with its Hit, its units (`displacement` is the whole move
// of one step: time 0 its start, 1 its end) and its edge rule (a hit is coming to share area
// at some 0 <= time < 1). The maths runs in double, so a 10^6 px/s mover gets exact times.
// RANGE (Range.h): every centre, radius and displacement within +-exactRange (1e6 px), as for
// the circle tests of Overlap.h (for two moving circles: the relative move); outside it (and
// NaN, infinity): no hit. A box target may be any finite box.
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

namespace hitbox
{

// A circle moving by `displacement` against a still circle: the smaller root of the quadratic
// |centres' distance at time t| = sum of the radii (Ericson, Real-Time Collision Detection,
// 5.5.5). Grazing (a tangent path) or touching only at time 1: no hit. Overlapping already:
// time 0, startedInside, circleVsCircleContact's push-out. Radius 0 is a point (a ray cast);
// two radius-0 circles never hit. Negative radius, NaN or infinite: no hit.
// `point`: where the rims touch.
[[nodiscard]] Hit sweepCircleVsCircle(const Circle& mover, Vec2 displacement, const Circle& target);

// Both circles move: sweepCircleVsCircle of the relative move (moverDisplacement -
// targetDisplacement, Ericson 5.5.5), same edge rules. `point` is in the world at that time.
[[nodiscard]] Hit sweepCircleVsMovingCircle(const Circle& mover, Vec2 moverDisplacement,
                                            const Circle& target, Vec2 targetDisplacement);

// A circle moving by `displacement` against a still box: its centre cast against the box grown
// by the radius (two slabs and four corner circles); the earliest entry wins and a tie goes to
// the face. `normal`: the face normal, or corner-to-centre on a corner. Overlapping already:
// circleVsBoxContact's push-out. Other edge rules as sweepCircleVsCircle; negative box sizes
// are read as normalised() reads them.
[[nodiscard]] Hit sweepCircleVsBox(const Circle& mover, Vec2 displacement, const Box& box);

} // namespace hitbox
