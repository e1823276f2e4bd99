#include "hitbox/geometry/Shapes.h"

#include <cmath>

namespace hitbox
{

Vec2 centerOf(const Box& box)
{
    return {box.left + box.width / 2.f, box.top + box.height / 2.f};
}

Circle inscribedCircle(const Box& box)
{
    return {centerOf(box), std::fmin(std::fabs(box.width), std::fabs(box.height)) / 2.f};
}

float rightOf(const Box& box)
{
    return box.left + box.width;
}

float bottomOf(const Box& box)
{
    return box.top + box.height;
}

bool isFinite(const Box& box)
{
    return std::isfinite(box.left) && std::isfinite(box.top) && std::isfinite(box.width) &&
           std::isfinite(box.height);
}

bool isFinite(const Circle& circle)
{
    return isFinite(circle.center) && std::isfinite(circle.radius);
}

} // namespace hitbox
