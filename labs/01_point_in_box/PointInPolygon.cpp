#include "PointInPolygon.h"

#include <cstddef>

// [slide:lab01-point-in-polygon]
// The crossing-number test: follow a ray from the point to the right (+x) and count the
// edges it crosses. An edge from a to b crosses the ray's line when one end is below it and
// the other is not (so a corner on the ray counts once); it counts when it crosses right
// of the point. An odd count is inside.
bool isInsidePolygon(const std::vector<sf::Vector2f>& corners, sf::Vector2f point)
{
    // BEGIN TASK 4: point in a polygon
    bool inside = false;
    const std::size_t count = corners.size();
    for (std::size_t index = 0; index < count; ++index)
    {
        const sf::Vector2f a = corners[index];
        const sf::Vector2f b = corners[(index + 1) % count];
        const sf::Vector2f ab = b - a;
        const sf::Vector2f ap = point - a;
        const float along = ab.x * ap.x + ab.y * ap.y; // 0 at a, |ab|^2 at b
        if (ab.x * ap.y == ab.y * ap.x && along >= 0.f && along <= ab.x * ab.x + ab.y * ab.y)
            return false; // on the edge (or a corner): touching is not colliding
        const bool crossesLine = (a.y > point.y) != (b.y > point.y);
        if (crossesLine && a.x + ap.y * ab.x / ab.y > point.x)
            inside = !inside;
    }
    return inside;
    // STARTER TASK 4
    // (void)corners;
    // (void)point;
    // return false;
    // END TASK 4
}
// [/slide]
