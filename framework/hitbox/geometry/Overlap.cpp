#include "hitbox/geometry/Overlap.h"

#include "hitbox/geometry/Range.h"

#include <cmath>
#include <limits>

namespace hitbox
{
namespace
{

float lengthSquared(Vec2 vector)
{
    return vector.x * vector.x + vector.y * vector.y;
}

// Inside the exact range (Range.h) only: at r = 1e20 a float cannot tell 3e19 from 0 apart,
// and radii of 2e38 add up to infinity, so outside it the answer is "no hit".
bool isUsable(const Circle& circle)
{
    return isFinite(circle) && circle.radius >= 0.f && withinExactRange(circle.center) &&
           withinExactRange(circle.radius);
}

// The point of the box nearest to `point` (the point itself when it is inside).
// [slide:closest-point-in-box]
Vec2 closestPointInBox(Vec2 point, const Box& box)
{
    return {std::fmin(std::fmax(point.x, box.left), rightOf(box)),
            std::fmin(std::fmax(point.y, box.top), bottomOf(box))};
}
// [/slide]

// The depth of an overlap the yes/no test found, worked out in double from the same float
// numbers. Rounding can make a real but tiny overlap come out as 0 in float; a hit must
// still have a depth above 0 (Shapes.h), so it becomes the smallest float above 0.
float overlapDepth(float reach, float distanceSquared)
{
    const double depth = double(reach) - std::sqrt(double(distanceSquared));
    return std::fmax(static_cast<float>(depth), std::numeric_limits<float>::denorm_min());
}

} // namespace

// [slide:point-in-box]
bool pointInBox(Vec2 point, const Box& box)
{
    if (!isFinite(point) || !isFinite(box))
        return false;
    const Box b = normalised(box);
    // A point is a span of length 0: on an edge it only touches, so it is outside.
    return spansOverlap(point.x, point.x, b.left, rightOf(b)) &&
           spansOverlap(point.y, point.y, b.top, bottomOf(b));
}
// [/slide]

bool pointInCircle(Vec2 point, const Circle& circle)
{
    return circleVsCircle(Circle{point, 0.f}, circle);
}

// [slide:aabb-overlap]
bool boxVsBox(const Box& first, const Box& second)
{
    if (!isFinite(first) || !isFinite(second))
        return false;
    const Box a = normalised(first);
    const Box b = normalised(second);
    // Two boxes overlap when their x ranges overlap AND their y ranges overlap.
    // spansOverlap carries the edge rule: boxes that only touch do not collide.
    return spansOverlap(a.left, rightOf(a), b.left, rightOf(b)) &&
           spansOverlap(a.top, bottomOf(a), b.top, bottomOf(b));
}
// [/slide]

// [slide:circle-overlap]
bool circleVsCircle(const Circle& a, const Circle& b)
{
    if (!isUsable(a) || !isUsable(b))
        return false;
    // Compare squared distances: same answer as comparing distances, no square root.
    const Vec2 between = a.center - b.center;
    const float radiusSum = a.radius + b.radius;
    return lengthSquared(between) < radiusSum * radiusSum;
}
// [/slide]

// [slide:circle-box-clamp]
bool circleVsBox(const Circle& circle, const Box& box)
{
    if (!isUsable(circle) || !isFinite(box))
        return false;
    const Box b = normalised(box);
    if (pointInBox(circle.center, b))
        return true;
    const Vec2 fromBox = circle.center - closestPointInBox(circle.center, b);
    return lengthSquared(fromBox) < circle.radius * circle.radius;
}
// [/slide]

// [slide:aabb-contact]
Contact boxVsBoxContact(const Box& first, const Box& second)
{
    Contact contact;
    if (!boxVsBox(first, second))
        return contact;
    const Box a = normalised(first);
    const Box b = normalised(second);

    // How far A must move each way to stop overlapping B; the shortest wins.
    const float pushLeft = rightOf(a) - b.left;
    const float pushRight = rightOf(b) - a.left;
    const float pushUp = bottomOf(a) - b.top;
    const float pushDown = bottomOf(b) - a.top;
    const float pushX = std::fmin(pushLeft, pushRight);
    const float pushY = std::fmin(pushUp, pushDown);

    // The middle of the shared region, used for the contact point.
    const float sharedMidX = (std::fmax(a.left, b.left) + std::fmin(rightOf(a), rightOf(b))) / 2.f;
    const float sharedMidY = (std::fmax(a.top, b.top) + std::fmin(bottomOf(a), bottomOf(b))) / 2.f;

    contact.hit = true;
    if (pushX <= pushY) // ties go to the x axis
    {
        const bool left = pushLeft <= pushRight;
        contact.normal = {left ? -1.f : 1.f, 0.f};
        contact.depth = pushX;
        contact.point = {left ? b.left : rightOf(b), sharedMidY};
    }
    else
    {
        const bool up = pushUp <= pushDown;
        contact.normal = {0.f, up ? -1.f : 1.f};
        contact.depth = pushY;
        contact.point = {sharedMidX, up ? b.top : bottomOf(b)};
    }
    return contact;
}
// [/slide]

Contact circleVsCircleContact(const Circle& a, const Circle& b)
{
    Contact contact;
    if (!circleVsCircle(a, b))
        return contact;
    const Vec2 between = a.center - b.center;
    const float distance = std::sqrt(lengthSquared(between));
    // Same centre: no direction is better than another; push A towards -x (documented).
    contact.normal = distance > 0.f ? between / distance : Vec2(-1.f, 0.f);
    contact.depth = overlapDepth(a.radius + b.radius, lengthSquared(between));
    contact.point = b.center + contact.normal * b.radius;
    contact.hit = true;
    return contact;
}

Contact circleVsBoxContact(const Circle& circle, const Box& box)
{
    Contact contact;
    if (!circleVsBox(circle, box))
        return contact;
    const Box b = normalised(box);
    const Vec2 closest = closestPointInBox(circle.center, b);
    const Vec2 fromBox = circle.center - closest;
    const float distanceSquared = lengthSquared(fromBox);
    contact.hit = true;

    if (distanceSquared > 0.f)
    {
        // Centre outside the box: push along the line from the nearest box point.
        const float distance = std::sqrt(distanceSquared);
        contact.normal = fromBox / distance;
        contact.depth = overlapDepth(circle.radius, distanceSquared);
        contact.point = closest;
        return contact;
    }

    // Centre inside the box (or on its edge): leave through the nearest edge.
    // Ties are broken in the order left, right, top, bottom.
    const float toLeft = circle.center.x - b.left;
    const float toRight = rightOf(b) - circle.center.x;
    const float toTop = circle.center.y - b.top;
    const float toBottom = bottomOf(b) - circle.center.y;
    const float nearest = std::fmin(std::fmin(toLeft, toRight), std::fmin(toTop, toBottom));
    if (nearest == toLeft)
    {
        contact.normal = {-1.f, 0.f};
        contact.point = {b.left, circle.center.y};
    }
    else if (nearest == toRight)
    {
        contact.normal = {1.f, 0.f};
        contact.point = {rightOf(b), circle.center.y};
    }
    else if (nearest == toTop)
    {
        contact.normal = {0.f, -1.f};
        contact.point = {circle.center.x, b.top};
    }
    else
    {
        contact.normal = {0.f, 1.f};
        contact.point = {circle.center.x, bottomOf(b)};
    }
    contact.depth = circle.radius + nearest;
    return contact;
}

} // namespace hitbox
