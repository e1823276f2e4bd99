// SweptCircle.h - where along a move does a circle first hit a circle or a box?
//
// The circle versions of Sweep.h. A moving circle touches a still circle when the distance
// between the centres equals the sum of the radii; writing the mover's centre as
// start + t * displacement turns that into a quadratic in t (Ericson, Real-Time Collision
// Detection, 5.5.5), and the smaller root is the time of impact. A circle against a box is a point
// against the box grown by the radius on every side: the "rounded box" (two slabs plus a circle at
// each corner).
//
// Units: pixels. `displacement` is the whole move for this step (velocity * dt): time 0 is
// the start of the step, time 1 its end. The Hit type and its normal convention are those of
// Sweep.h: the normal is the target's surface normal, pointing back towards the mover.
//
// EDGE RULES (the "share area" rule of Overlap.h, followed through time, as in Sweep.h):
//   - A hit means the mover would come to SHARE AREA with the target during the step
//     (0 <= t < 1); `time` is when they first touch. Grazing (touching without ever
//     overlapping, a tangent path) is not a hit, and neither is touching only at t == 1.
//   - Already sharing area at time 0: hit, startedInside == true, time 0, and normal, depth
//     and point are the push-out of circleVsCircleContact / circleVsBoxContact (Overlap.h).
//     Same centres: the normal is (-1, 0), as in circleVsCircleContact.
//   - Starting exactly touching and moving in: hit at time 0, startedInside == false.
//     Starting exactly touching and moving away or along: no hit.
//   - Zero displacement: the discrete test (startedInside or no hit).
//   - Zero radius: a point, which hits when it passes strictly inside. Two shapes with no
//     area (a zero-radius mover against a zero-radius target) never hit.
//   - Negative radius, NaN or infinite input: no hit.
//   - The maths runs in double precision, so a 10^6 px/s mover still gets exact times.
#pragma once

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"

namespace hitbox
{

// A point moving from `start` to `end` against a circle (the ray cast of a circle). `point`
// is where the segment crosses the circle's rim; `normal` points from the centre out through
// that point.
Hit segmentVsCircle(Vec2 start, Vec2 end, const Circle& circle);

// A circle moving by `displacement` against a circle that stays still: the time of impact
// from that quadratic. `point` is where the two rims touch at that time.
Hit sweepCircleVsCircle(const Circle& mover, Vec2 displacement, const Circle& target);

// Both circles move during the step. Only the relative move matters (Ericson, 5.5.5),
// so this sweeps the mover by (moverDisplacement - targetDisplacement) against a still
// target. `point` is where they touch in the world at that time.
Hit sweepCircleVsMovingCircle(const Circle& mover, Vec2 moverDisplacement, const Circle& target,
                              Vec2 targetDisplacement);

// A circle moving by `displacement` against a still box. Its centre is cast against the
// rounded box (the box grown by the radius: two slabs and four corner circles), and the
// earliest entry wins. `point` is on the box's surface (a corner when the rounded corner was
// hit); `normal` is the face normal on a face, the corner-to-centre direction on a corner.
// Ties between a face and a corner go to the face (so an exact corner still gets a unit
// normal). Negative box sizes are read as SFML reads them; a zero-size box is a point or a
// line, hit when the circle's area reaches it.
Hit sweepCircleVsBox(const Circle& mover, Vec2 displacement, const Box& box);

} // namespace hitbox
