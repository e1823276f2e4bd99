// Overlap.h - is a shape inside another? Points, boxes and circles that are not moving.
//
// One edge rule for every test in Hitbox: two shapes collide only when they share area
// (spansOverlap, Shapes.h). Touching is not colliding, because a response that pushes two
// objects apart leaves them exactly touching; if that counted they would collide again next
// frame (the sticking bug). It is also how sf::Rect::intersects reads boxes.
//
// THE RANGE (Range.h): a circle test is exact for centres and radii within +-exactRange
// (1e6 px) and answers "no hit" outside it (and for NaN or infinity). Box tests take any
// finite box (the broadphases test huge bounds) and answer NaN with "no hit".
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

// True when the point is strictly inside: a point on an edge or a corner is outside.
// A zero-size box contains nothing; NaN or infinite: false.
[[nodiscard]] bool pointInBox(Vec2 point, const Box& box);
// True when the point is strictly inside: a point on the rim is outside. No square root.
// Negative or NaN radius: false.
[[nodiscard]] bool pointInCircle(Vec2 point, const Circle& circle);
// True when the boxes share area: touching edges or corners do not. A zero-size box (a point
// or a line) collides when it lies strictly inside the other (sf::Rect::intersects never
// reports one); negative sizes span backwards; NaN or infinite: false.
[[nodiscard]] bool boxVsBox(const Box& a, const Box& b);
// True when the centres are closer than the sum of the radii (squared, no square root):
// touching rims do not. Radius 0 is a point; negative radius or NaN: false.
[[nodiscard]] bool circleVsCircle(const Circle& a, const Circle& b);
// True when the box's closest point to the centre (Ericson, Real-Time Collision Detection,
// 5.1.3) is strictly inside the circle, or the centre is strictly inside the box.
[[nodiscard]] bool circleVsBox(const Circle& circle, const Box& box);

// boxVsBox with the push-out: along the axis of least overlap, ties to the x axis.
// `normal` points out of b towards a (Contact, Shapes.h).
[[nodiscard]] Contact boxVsBoxContact(const Box& a, const Box& b);
// circleVsCircle with the push-out along the centres' line. Same centres: normal (-1, 0).
[[nodiscard]] Contact circleVsCircleContact(const Circle& a, const Circle& b);
// circleVsBox with the push-out; a centre inside the box is pushed out of the nearest edge.
[[nodiscard]] Contact circleVsBoxContact(const Circle& circle, const Box& box);

} // namespace hitbox
