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
    for (std::size_t index = 0; index < corners.size(); ++index)
    {
        const sf::Vector2f a = corners[index];
        const sf::Vector2f b = corners[(index + 1) % corners.size()];
        const sf::Vector2f ab = b - a;
        const sf::Vector2f ap = point - a;
        // On the edge: on the line through a and b (cross product 0) and between them.
        const bool onLine = ab.x * ap.y - ab.y * ap.x == 0.f;
        const float along = ab.x * ap.x + ab.y * ap.y; // from 0 at a to |ab|^2 at b
        if (onLine && along >= 0.f && along <= ab.x * ab.x + ab.y * ab.y)
            return false; // touching is not colliding
        if ((a.y > point.y) != (b.y > point.y) && a.x + ap.y * ab.x / ab.y > point.x)
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
