// Framework/GameObject.h (2025-26 course framework) - a rectangle shape that moves and
// collides, as the course's current framework has it: m_ members, collisionResponse taking a
// reference, and a new object that is not a collider until setCollider(true).
//
// It is Hitbox's GameObject (hitbox/objects/GameObject.h) under the course's names, so the
// box, its negative-size rule and the bounding circle are Hitbox's: the collision box is
// measured from the object's position (its origin point); until one is set (a box of zero
// size) it is the whole shape; scale and rotation are applied (rotated: the axis-aligned box
// around the turned box).
#pragma once

#include <SFML/Graphics.hpp>

#include "Framework/Input.h"
#include "hitbox/objects/GameObject.h"

#include <optional>

class GameObject : public hitbox::GameObject
{
public:
    GameObject();
    // The m_ names below refer to this object's own state, in a copy too.
    GameObject(const GameObject& other);
    GameObject& operator=(const GameObject& other);
    ~GameObject() override = default;

    // Called by the lab's own code when this object hits `collider`. Does nothing by default.
    virtual void collisionResponse(GameObject& collider);

    // The box relative to the object's position (its origin point), in unscaled pixels; a box
    // of zero size means "the whole shape".
    void setCollisionBox(float x, float y, float width, float height);
    void setCollisionBox(sf::FloatRect box);

    void setInput(Input* input);
    void setWindow(sf::RenderWindow* window);

protected:
    // The course's names for Hitbox's own state (references to it), so that code writing
    // m_velocity and code calling getVelocity() see one velocity.
    sf::Vector2f& m_velocity = velocity;
    bool& m_alive = alive;
    bool& m_collider = collider;
    sf::FloatRect m_collisionBox; // zero size: not set, the whole shape is used
    Input* m_input = nullptr;
    sf::RenderWindow* m_window = nullptr;

private:
    [[nodiscard]] std::optional<hitbox::Box> givenCollisionBox() const override;
    // A World calls Hitbox's hook: handed on when `other` is one of these.
    void collisionResponse(hitbox::GameObject* other) final;
};
