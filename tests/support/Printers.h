// Printers.h - GoogleTest printers, so a failure reads FloatRect{x=10, y=0, w=50, h=50}
// instead of a dump of bytes. Include it in every test file that compares these types.
#pragma once

#include "hitbox/geometry/Shapes.h"

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
inline void PrintTo(const FloatRect& box, std::ostream* out)
{
    *out << "FloatRect{x=" << box.left << ", y=" << box.top << ", w=" << box.width
         << ", h=" << box.height << "}";
}
} // namespace sf

namespace hitbox
{
inline void PrintTo(const Circle& circle, std::ostream* out)
{
    *out << "Circle{center=(" << circle.center.x << ", " << circle.center.y
         << "), radius=" << circle.radius << "}";
}
inline void PrintTo(const Contact& contact, std::ostream* out)
{
    if (!contact.hit)
    {
        *out << "Contact{no hit}";
        return;
    }
    *out << "Contact{normal=(" << contact.normal.x << ", " << contact.normal.y
         << "), depth=" << contact.depth << ", point=(" << contact.point.x << ", "
         << contact.point.y << ")}";
}
} // namespace hitbox
