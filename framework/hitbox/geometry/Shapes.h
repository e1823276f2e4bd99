// Shapes.h - the plain value types every collision test works on.
//
// Units are pixels (world units) and seconds. Boxes are sf::FloatRect (left, top, width,
// height), vectors are sf::Vector2f: the types SFML students already know. Nothing here
// draws or needs a window.
#pragma once

#include <SFML/Graphics/Rect.hpp>
#include <SFML/System/Vector2.hpp>

#include <cmath>

namespace hitbox
{

// A circle: centre in world pixels, radius in pixels. A negative radius is not a circle and
// never collides; a zero radius is a point.
struct Circle
{
    sf::Vector2f center;
    float radius = 0.f;
};

// What a test found. The convention is the same for every contact test in Hitbox:
// `normal` is a unit vector pointing out of the second shape (B) towards the first (A), so
// moving A by `normal * depth` separates the two (the minimum translation vector).
struct Contact
{
    bool hit = false;    // true only when the shapes share area (see Overlap.h's edge rules)
    sf::Vector2f normal; // unit length when hit, (0, 0) otherwise
    float depth = 0.f;   // penetration depth in pixels, > 0 when hit
    sf::Vector2f point;  // a point where they touch, on B's surface

    explicit operator bool() const { return hit; }
};

// Box helpers.
// The size that takes `from` exactly to `to` (from <= to): to - from, nudged by a float step
// when rounding would make from + size miss `to`. Without it a flipped box's edge could move
// by a rounding error, and boxes that only touch would overlap.
inline float sizeReaching(float from, float to)
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
inline sf::FloatRect normalised(const sf::FloatRect& box)
{
    sf::FloatRect result = box;
    if (box.width < 0.f)
    {
        result.left = box.left + box.width;
        result.width = sizeReaching(result.left, box.left);
    }
    if (box.height < 0.f)
    {
        result.top = box.top + box.height;
        result.height = sizeReaching(result.top, box.top);
    }
    return result;
}
sf::Vector2f centerOf(const sf::FloatRect& box);
float rightOf(const sf::FloatRect& box);
float bottomOf(const sf::FloatRect& box);

// True when every coordinate is a finite number (no NaN, no infinity).
bool isFinite(sf::Vector2f point);
bool isFinite(const sf::FloatRect& box);
bool isFinite(const Circle& circle);

} // namespace hitbox
