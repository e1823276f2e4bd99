// Lab 1's hints are written inside PointInBoxLevel (tasks 1-3) and PointInPolygon.cpp (task 4).
#pragma once
#include "PointInBoxLevel.h"
#include "hitbox/objects/Collision.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/View.hpp>
#include <SFML/System/Vector2.hpp>
#include <vector>

// not code: getInverse()

struct HintScope
{
    void hints();
    std::vector<hitbox::GameObject> boxes;
    std::size_t index, i;
    sf::Vector2f scenePoint, mouse;
    sf::RenderWindow& window;
    sf::Vector2i pixel;
    sf::View view;
    sf::Vector2f a, b, point; // task 4: an edge from a to b, and the point
    float x;
};
