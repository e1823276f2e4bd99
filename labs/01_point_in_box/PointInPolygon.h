// PointInPolygon.h - task 4 of lab 1: is a point inside a polygon that may be concave?
//
// A box has four straight sides along the axes; most shapes in a game do not. The test
// students write here is the crossing-number test: from the point, follow a ray to the right
// and count the polygon's edges it crosses; an odd count means inside (Haines, "Point in
// Polygon Strategies", Graphics Gems IV, 1994). The framework's version, with its result
// struct and edge rules, is hitbox::pointInPolygon (hitbox/geometry/PointInPolygon.h).
#pragma once

#include <SFML/System/Vector2.hpp>

#include <vector>

// True when `point` is strictly inside the polygon whose corners are `corners`, in order
// around the edge (either way round; concave allowed). Edge rule: a point on an edge or
// a corner is not inside (touching is not colliding). Fewer than 3 corners: never inside.
bool isInsidePolygon(const std::vector<sf::Vector2f>& corners, sf::Vector2f point);
