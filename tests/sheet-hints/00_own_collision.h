// Lab 0's hints are written inside MyCollision's functions (MyCollision.cpp).
#pragma once
#include "MyCollision.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/System/Vector2.hpp>
#include <algorithm>

struct HintScope : MyCollision
{
    void hints();
    const hitbox::GameObject& object; // worldBox(object)
    sf::Vector2f p;                   // a corner, measured from the top-left
    Sides a, b, box;                  // world boxes
    bool apart;                       // "the boxes are apart": task 2's NaN hint
    float dx, dy, r1, r2;             // task 4: the centres' offset and the radii
    sf::Vector2f center;              // task 5: the circle's centre
    sf::Vector2f getSize() const;     // not to use: the picture's size (a shape's getSize())
};
