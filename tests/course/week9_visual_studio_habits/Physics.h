#pragma once
#include "Framework/Vector.h"

// The student's own maths helpers, built on the framework's Vector by deriving from it.
class Physics : public Vector
{
public:
	static float speed(sf::Vector2f velocity)
	{
		return magnitude(velocity);
	}
	static float distance(sf::Vector2f a, sf::Vector2f b)
	{
		return std::sqrt(pow(b.x - a.x, 2) + pow(b.y - a.y, 2));
	}
};
