// Shapes.h - the plain value types every collision test works on.
//
// Units are pixels (world units) and seconds. Boxes (left, top, width, height) and vectors
// (Vec2.h) are Hitbox's own plain values: nothing here knows SFML, draws or needs a window
// (framework/hitbox/sfml/Conversions.h converts to and from Box / Vec2).
// RANGE: the types hold any float; each test states the range it is exact in (Range.h:
// +-exactRange, 1e6 px). The helpers here (normalised, centerOf, rightOf, bottomOf) round
// as float sums do and are exact to the last bit inside that range; past about 3.4e38 a sum
// overflows to infinity, which every test then answers with "no hit".
#pragma once

#include "hitbox/geometry/Vec2.h"

#include <cmath>

namespace hitbox
{

// An axis-aligned box: top-left corner and size in pixels, the fields of Box.
// A negative width or height spans backwards from left/top (see normalised()).
struct Box
{
    float left = 0.f;
    float top = 0.f;
    float width = 0.f;
    float height = 0.f;

    constexpr Box() = default;
    constexpr Box(float leftValue, float topValue, float widthValue, float heightValue)
        : left(leftValue), top(topValue), width(widthValue), height(heightValue)
    {
    }
    constexpr Box(Vec2 topLeft, Vec2 size)
        : left(topLeft.x), top(topLeft.y), width(size.x), height(size.y)
    {
    }
};
// Exact comparison of the four fields.
[[nodiscard]] constexpr bool operator==(const Box& a, const Box& b)
{
    return a.left == b.left && a.top == b.top && a.width == b.width && a.height == b.height;
}
[[nodiscard]] constexpr bool operator!=(const Box& a, const Box& b)
{
    return !(a == b);
}

// A circle: centre in world pixels, radius in pixels. A negative radius is not a circle and
// never collides; a zero radius is a point.
struct Circle
{
    Vec2 center;
    float radius = 0.f;
};

// What a test found. The convention is the same for every contact test in Hitbox:
// `normal` is a unit vector pointing out of the second shape (B) towards the first (A), so
// moving A by `normal * depth` separates the two (the minimum translation vector).
struct Contact
{
    bool hit = false;  // true only when the shapes share area (see Overlap.h's edge rules)
    Vec2 normal;       // unit length when hit, (0, 0) otherwise
    float depth = 0.f; // penetration depth in pixels, > 0 when hit
    Vec2 point;        // a point where they touch, on B's surface

    explicit operator bool() const { return hit; }
};

// THE EDGE RULE, in one place: the spans minA..maxA and minB..maxB overlap only when they
// share some length; spans that only touch (maxA == minB) do not, and NaN never overlaps.
// `&` instead of `&&`: no branch for the CPU to mispredict in the broadphases' inner loops.
[[nodiscard]] inline bool spansOverlap(float minA, float maxA, float minB, float maxB)
{
    return (minA < maxB) & (minB < maxA);
}
// The same rule for a penetration depth (the shortest move that separates two shapes): they
// collide only when it is > 0; 0 (touching) and NaN do not. Every Contact test ends with it.
[[nodiscard]] inline bool penetrates(float depth)
{
    return depth > 0.f;
}

// The size that takes `from` exactly to `to` (from <= to): to - from, nudged by a float step
// when rounding would make from + size miss `to`. Without it a flipped box's edge could move
// by a rounding error, and boxes that only touch would overlap.
[[nodiscard]] inline float exactSizeBetween(float from, float to)
{
    float size = to - from;
    for (int nudge = 0; nudge < 4 && from + size != to; ++nudge)
        size = std::nextafter(size, from + size < to ? HUGE_VALF : -HUGE_VALF);
    return size;
}
// A box with a negative width or height spans from left + width to left (the way
// sf::Rect::intersects reads it); normalised() turns it into the usual form, whose right edge
// (left + width) is the original left to the last bit. Inline: the broadphases run it for
// every box every frame, and a call into another file is not inlined.
[[nodiscard]] inline Box normalised(const Box& box)
{
    Box result = box;
    if (box.width < 0.f)
    {
        result.left = box.left + box.width;
        result.width = exactSizeBetween(result.left, box.left);
    }
    if (box.height < 0.f)
    {
        result.top = box.top + box.height;
        result.height = exactSizeBetween(result.top, box.top);
    }
    return result;
}
// The middle of the box (the same point for a negative size).
[[nodiscard]] Vec2 centerOf(const Box& box);
// The circle inscribed in the box: centred on its middle, radius half its shorter side (a
// negative size counts as its length, as normalised() reads it). The default bounding circle
// of every GameObject, the course's included.
[[nodiscard]] Circle inscribedCircle(const Box& box);
// left + width: the right edge (for a negative width, the left one; normalised() first).
[[nodiscard]] float rightOf(const Box& box);
// top + height: the bottom edge (for a negative height, the top one; normalised() first).
[[nodiscard]] float bottomOf(const Box& box);

// True when every coordinate is a finite number (no NaN, no infinity).
[[nodiscard]] bool isFinite(const Box& box);
[[nodiscard]] bool isFinite(const Circle& circle);

} // namespace hitbox
