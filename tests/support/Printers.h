// Printers.h - GoogleTest printers, so a failure reads Box{x=10, y=0, w=50, h=50}
// instead of a dump of bytes. Include it in every test file that compares these types.
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <ostream>

namespace hitbox
{
inline void PrintTo(const Vec2& vector, std::ostream* out)
{
    *out << "Vec2{" << vector.x << ", " << vector.y << "}";
}
inline void PrintTo(const Box& box, std::ostream* out)
{
    *out << "Box{x=" << box.left << ", y=" << box.top << ", w=" << box.width << ", h=" << box.height
         << "}";
}
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
