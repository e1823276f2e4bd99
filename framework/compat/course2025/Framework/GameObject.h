// Framework/GameObject.h (2025-26 course framework) - a rectangle shape that moves and
// collides, as the course's current framework has it: references, m_ members, and a new
// object that is not a collider until setCollider(true).
//
// The collision box is measured from the object's position (its origin point), as in the
// older framework; until one is set (a box of zero size) it is the whole shape. Scale and
// rotation are applied (rotated: the axis-aligned box around the turned box).
#pragma once

#include <SFML/Graphics.hpp>

#include "Framework/Input.h"

class GameObject : public sf::RectangleShape
{
public:
    virtual ~GameObject() = default;

    virtual void handleInput(float dt);
    virtual void update(float dt);
    // Called by the lab's own code when this object hits `collider`.
    virtual void collisionResponse(GameObject& collider);

    void setVelocity(sf::Vector2f velocity);
    void setVelocity(float x, float y);
    sf::Vector2f getVelocity() const;

    bool isAlive() const;
    void setAlive(bool alive);
    bool isCollider() const;
    void setCollider(bool collider);

    // The collision box in world coordinates.
    sf::FloatRect getCollisionBox() const;
    // The box relative to the object's position (its origin point), in unscaled pixels.
    void setCollisionBox(float x, float y, float width, float height);
    void setCollisionBox(sf::FloatRect box);

    void setInput(Input* input);
    void setWindow(sf::RenderWindow* window);

protected:
    sf::Vector2f m_velocity;
    bool m_alive = true;
    sf::FloatRect m_collisionBox; // zero size: not set, the whole shape is used
    bool m_collider = false;
    Input* m_input = nullptr;
    sf::RenderWindow* m_window = nullptr;
};
