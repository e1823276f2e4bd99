// Explain.h - why two shapes do or do not collide, in words a first-year reads, test by test.
//
//     const hitbox::Explanation why = hitbox::explainBoxes(player, wall);
//     // why.verdict: "A and B do not collide: on x they only touch"
//     // why.steps:   "x: A [10, 30] and B [30, 50] only touch - touching is not a collision"
//     //              "y: A [0, 20] and B [5, 40] overlap by 15"
//
// Each function runs the same test as Overlap.h / Polygon.h / Sweep.h and always agrees with
// it: `collides` is that test's answer, and the steps show the numbers it compared. Plain
// data (no SFML): the debug overlay draws it, the test matchers print it.
// RANGE: each explanation takes the range of the test it explains (Overlap.h, Polygon.h,
// Sweep.h; Range.h's +-exactRange), and outside it says what that test says: no collision.
#pragma once

#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Shapes.h"

#include <string>
#include <vector>

namespace hitbox
{

struct Explanation
{
    bool collides = false;          // the test's own answer (for a sweep: does the move hit)
    std::string verdict;            // one sentence: the answer and the test that decided it
    std::vector<std::string> steps; // one line per thing the test compared, in its order
};

// The verdict, then each step on its own line indented by two spaces.
[[nodiscard]] std::string toText(const Explanation& explanation);

// Axis-aligned boxes: the x spans, then the y spans (boxVsBox). Negative sizes are
// normalised first; NaN or infinity never collides.
[[nodiscard]] Explanation explainBoxes(const Box& a, const Box& b, const std::string& nameA = "A",
                                       const std::string& nameB = "B");
// Circles: squared distance between centres against the squared radius sum (circleVsCircle).
[[nodiscard]] Explanation explainCircles(const Circle& a, const Circle& b,
                                         const std::string& nameA = "A",
                                         const std::string& nameB = "B");
// A circle and a box: the box's point nearest the centre, then its squared distance against
// the squared radius (circleVsBox).
[[nodiscard]] Explanation explainCircleBox(const Circle& circle, const Box& box,
                                           const std::string& nameA = "A",
                                           const std::string& nameB = "B");
// Convex polygons (the separating axis theorem, polygonVsPolygon): every edge normal of
// both hulls as an axis, both shadows on it, and which axis separates them.
[[nodiscard]] Explanation explainPolygons(const Polygon& a, const Polygon& b,
                                          const std::string& nameA = "A",
                                          const std::string& nameB = "B");
// A box moving by `displacement` against a still box (sweepBoxVsBox): per axis the times
// (fractions of the move) at which the spans start and stop overlapping, then whether the
// two stretches meet inside the move.
[[nodiscard]] Explanation explainSweep(const Box& mover, Vec2 displacement, const Box& target,
                                       const std::string& nameA = "A",
                                       const std::string& nameB = "B");

} // namespace hitbox
