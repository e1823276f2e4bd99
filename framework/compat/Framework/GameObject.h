// Framework/GameObject.h - the course's GameObject (2019-24 generation): Hitbox's
// (hitbox/objects/GameObject.h) with what the course's lab code reaches for besides:
//   - `input` and `window`, the pointers setInput/setWindow hand it;
//   - `collisionBox`, the member old code assigns (`collisionBox = sf::FloatRect(...)`): a box
//     assigned there is the one every collision query reads, as one given to setCollisionBox;
//   - collisionResponse(GameObject* other) taking the course's GameObject, so old code's
//     `void collisionResponse(GameObject* other) override` overrides it, and a World (which
//     calls Hitbox's hook) still reaches it, with other == nullptr for the world.
// SFML's graphics and Input come along, as they did in the old header: lab code relies on them.
#pragma once

#include "Framework/Input.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics.hpp>

#include <optional>

class GameObject : public hitbox::GameObject
{
public:
    // Called when this object hits `other`; nullptr when it hit the world (a wall, the edge
    // of the screen). Does nothing by default.
    virtual void collisionResponse(GameObject* other);

    // The box relative to the object's position (its origin point), in unscaled pixels:
    // stored in `collisionBox`, where old code may also assign it.
    void setCollisionBox(float left, float top, float width, float height);
    void setCollisionBox(const sf::FloatRect& box);
    // Back to "the box is the whole shape".
    void clearCollisionBox();

    // The course framework hands every object the input and the window it may use.
    void setInput(Input* newInput);
    void setWindow(sf::RenderWindow* newWindow);

protected:
    // A box relative to the origin point, and whether one was given. Assigning an
    // sf::FloatRect counts as giving one; until then it reads {0, 0, 0, 0}, as in the course.
    struct AssignedBox : sf::FloatRect
    {
        bool isSet = false;
        AssignedBox& operator=(const sf::FloatRect& box);
    };

    AssignedBox collisionBox;
    Input* input = nullptr;
    sf::RenderWindow* window = nullptr;

private:
    [[nodiscard]] std::optional<hitbox::Box> givenCollisionBox() const override;
    // A World calls Hitbox's hook: handed on as the course's GameObject (an object that is
    // not one, which a course lab never has, arrives as nullptr).
    void collisionResponse(hitbox::GameObject* other) final;
};
