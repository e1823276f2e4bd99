// Vec2.h - Hitbox's own 2D vector, the vector helpers every geometry function shares, and π.
//
// Plain values in pixels (y down, as on screen). The geometry and broadphase layers use only
// these types, so they compile and are tested without SFML; framework/hitbox/sfml/
// Conversions.h turns them into SFML's types and back at the edge of the framework.
// RANGE: any float. The operators round as float arithmetic does (and overflow to infinity
// past about 3.4e38); length() and unitVectorOr() work in double, so they neither overflow
// nor lose tiny values. The tests built on these state their own range (Range.h).
#pragma once

#include <cmath>

namespace hitbox
{

// π, the one definition in Hitbox: use hitbox::pi (or piDouble where a double computation
// needs all its digits), never a copy of the digits.
constexpr double piDouble = 3.14159265358979323846;
constexpr float pi = static_cast<float>(piDouble);

struct Vec2
{
    float x = 0.f;
    float y = 0.f;

    constexpr Vec2() = default;
    constexpr Vec2(float xValue, float yValue) : x(xValue), y(yValue) {}

    Vec2& operator+=(Vec2 other)
    {
        x += other.x;
        y += other.y;
        return *this;
    }
    Vec2& operator-=(Vec2 other)
    {
        x -= other.x;
        y -= other.y;
        return *this;
    }
    Vec2& operator*=(float scale)
    {
        x *= scale;
        y *= scale;
        return *this;
    }
};

[[nodiscard]] constexpr Vec2 operator+(Vec2 a, Vec2 b)
{
    return {a.x + b.x, a.y + b.y};
}
[[nodiscard]] constexpr Vec2 operator-(Vec2 a, Vec2 b)
{
    return {a.x - b.x, a.y - b.y};
}
[[nodiscard]] constexpr Vec2 operator-(Vec2 a)
{
    return {-a.x, -a.y};
}
[[nodiscard]] constexpr Vec2 operator*(Vec2 a, float scale)
{
    return {a.x * scale, a.y * scale};
}
[[nodiscard]] constexpr Vec2 operator*(float scale, Vec2 a)
{
    return {a.x * scale, a.y * scale};
}
[[nodiscard]] constexpr Vec2 operator/(Vec2 a, float divisor)
{
    return {a.x / divisor, a.y / divisor};
}
// Exact comparison, as for floats: NaN is never equal to anything.
[[nodiscard]] constexpr bool operator==(Vec2 a, Vec2 b)
{
    return a.x == b.x && a.y == b.y;
}
[[nodiscard]] constexpr bool operator!=(Vec2 a, Vec2 b)
{
    return !(a == b);
}

// a.x * b.x + a.y * b.y: how far `a` goes along `b` (times |b|).
[[nodiscard]] constexpr float dot(Vec2 a, Vec2 b)
{
    return a.x * b.x + a.y * b.y;
}

// The z of the 3D cross product: > 0 when `b` turns clockwise from `a` on screen (y down).
[[nodiscard]] constexpr float cross(Vec2 a, Vec2 b)
{
    return a.x * b.y - a.y * b.x;
}

// The vector's length, computed in double so that huge and tiny components do not overflow.
[[nodiscard]] inline float length(Vec2 vector)
{
    return static_cast<float>(std::hypot(double(vector.x), double(vector.y)));
}

// `vector` scaled to length 1; `whenNoDirection` when it has none (zero, NaN, infinite).
[[nodiscard]] inline Vec2 unitVectorOr(Vec2 vector, Vec2 whenNoDirection)
{
    const double size = std::hypot(double(vector.x), double(vector.y));
    if (!(size > 0.0) || !std::isfinite(size))
        return whenNoDirection;
    return {static_cast<float>(vector.x / size), static_cast<float>(vector.y / size)};
}

// The vector turned a quarter turn (x, y) -> (-y, x): perpendicular, same length.
[[nodiscard]] constexpr Vec2 perpendicular(Vec2 vector)
{
    return {-vector.y, vector.x};
}

// True when both coordinates are finite numbers (no NaN, no infinity).
[[nodiscard]] inline bool isFinite(Vec2 point)
{
    return std::isfinite(point.x) && std::isfinite(point.y);
}

} // namespace hitbox
