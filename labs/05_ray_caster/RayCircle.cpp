#include "RayCircle.h"

#include <cmath>

// [slide:lab05-ray-circle]
float rayCircleTime(hitbox::Vec2 from, hitbox::Vec2 to, const hitbox::Circle& circle)
{
    // BEGIN TASK 4: a ray against a circle
    if (circle.radius <= 0.f)
        return rayMissed;                        // no area: nothing to get inside
    const hitbox::Vec2 d = to - from;            // the ray
    const hitbox::Vec2 f = from - circle.center; // from the centre to the start
    const float a = hitbox::dot(d, d);
    const float b = hitbox::dot(f, d);
    const float c = hitbox::dot(f, f) - circle.radius * circle.radius;
    if (c < 0.f)
        return 0.f; // started inside
    const float discriminant = b * b - a * c;
    if (a == 0.f || b >= 0.f || discriminant <= 0.f)
        return rayMissed; // not moving, heading away, missing, or only grazing
    // The smaller root: where it enters (at `to` exactly, it only touches).
    const float t = (-b - std::sqrt(discriminant)) / a;
    return t < 1.f ? t : rayMissed;
    // STARTER TASK 4
    // (void)from;
    // (void)to;
    // (void)circle;
    // return rayMissed;
    // END TASK 4
}
// [/slide]
