// Overlap.h - is a shape inside another? Points, boxes and circles that are not moving.
//
// THE EDGE RULE (the same in every test in Hitbox):
//   Two shapes collide only when one reaches strictly inside the other: the penetration
//   depth (the shortest move that separates them) must be > 0. Touching edges, touching
//   corners and a point exactly on an edge do NOT collide.
// Why: a response that pushes two objects apart leaves them exactly touching. If touching
// counted, they would "collide" again next frame and bounce back and forth (the sticking
// bug). It also matches sf::Rect::intersects, so SFML code and Hitbox agree.
//
// Degenerate input, each with a defined answer (tests in tests/geometry/):
//   - NaN or infinite coordinates: never collide (`false`, Contact with hit == false).
//   - Zero-size box: a point or a line; it collides when it lies strictly inside the other
//     (sf::Rect::intersects differs here: it never reports a zero-size box).
//   - Negative box size: the box spans from left + width to left, as in SFML.
//   - Zero radius: a point. Negative radius: not a circle, never collides.
//
// Every yes/no test has a Contact version returning the normal and the depth (see
// Shapes.h for the normal convention). The yes/no tests never take a square root.
#pragma once

#include "hitbox/geometry/Shapes.h"

namespace hitbox
{

bool pointInBox(Vec2 point, const Box& box);
bool pointInCircle(Vec2 point, const Circle& circle);
bool boxVsBox(const Box& a, const Box& b);
bool circleVsCircle(const Circle& a, const Circle& b);
bool circleVsBox(const Circle& circle, const Box& box);

// A = the point. Normal: out of the nearest edge of the box; depth: distance to that edge.
Contact pointInBoxContact(Vec2 point, const Box& box);
// A = the point. Normal: from the circle's centre towards the point.
Contact pointInCircleContact(Vec2 point, const Circle& circle);
// Pushes along the axis of least overlap. Equal overlaps: the x axis wins.
Contact boxVsBoxContact(const Box& a, const Box& b);
Contact circleVsCircleContact(const Circle& a, const Circle& b);
// A = the circle, B = the box. A centre inside the box is pushed out of the nearest edge.
Contact circleVsBoxContact(const Circle& circle, const Box& box);

} // namespace hitbox
