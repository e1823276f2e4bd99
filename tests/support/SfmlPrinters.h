// SfmlPrinters.h - GoogleTest printers for SFML's vectors and rectangles (Printers.h has
// Hitbox's own types), so a failure reads FloatRect{x=10, y=0, w=50, h=50}.
#pragma once

#include "Printers.h"
#include "hitbox/sfml/Conversions.h"

#include <ostream>

namespace sf
{
inline void PrintTo(const Vector2f& vector, std::ostream* out)
{
    *out << "Vector2f{" << vector.x << ", " << vector.y << "}";
}
inline void PrintTo(const Vector2i& vector, std::ostream* out)
{
    *out << "Vector2i{" << vector.x << ", " << vector.y << "}";
}
inline void PrintTo(const FloatRect& rect, std::ostream* out)
{
    const hitbox::Box box = hitbox::toBox(rect);
    *out << "FloatRect{x=" << box.left << ", y=" << box.top << ", w=" << box.width
         << ", h=" << box.height << "}";
}
} // namespace sf
