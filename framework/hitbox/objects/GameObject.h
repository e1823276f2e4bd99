// GameObject.h - a rectangle shape that moves and collides.
//
// The base class of every object in the labs and in Pong. The course's own GameObjects (its
// input and window pointers, the `collisionBox` member old lab code assigns) are built on this
// one in framework/compat/ (docs/course-labs.md); this class knows nothing of them.
//
// The collision box is measured from the object's position, i.e. from its origin point:
//     setOrigin({16, 16});
//     setCollisionBox(-16, -16, 32, 32);   // covers the whole 32 x 32 shape
// Until a box is set, the collision box is the whole shape and follows setSize/setOrigin.
#pragma once

#include "hitbox/objects/ContactEvent.h"
#include "hitbox/objects/WorldLinks.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/Graphics/RectangleShape.hpp>

#include <optional>
#include <string>

namespace hitbox
{
class World;

class GameObject : public sf::RectangleShape
{
public:
    // Alive, a collider, standing still, its collision box the whole shape.
    GameObject();
    // A copy is a new object: it is in no World until added (copying a level's objects into
    // a vector does not put the copies into the World).
    GameObject(const GameObject& other) = default;
    GameObject& operator=(const GameObject& other) = default;
    // An object destroyed while still in a World takes itself out (the World's other
    // objects get their Exit events, with other == nullptr), even from inside a response.
    ~GameObject() override;

    // Override these in your own objects. They do nothing by default.
    virtual void handleInput(float dt);
    virtual void update(float dt);
    // [slide:collision-response-hook]
    // Called when this object hits `other`. `other` is nullptr when it hit the world
    // (a wall, the edge of the screen) rather than another object.
    virtual void collisionResponse(GameObject* other);
    // [/slide]
    // Contact events from a World (ContactEvent.h): Enter the first step this object collides
    // with another, Stay every further step, Exit the first step they no longer do (or the
    // other left the World, died, was destroyed, stopped being a collider). Each is called
    // after both collisionResponse calls of the step. They do nothing by default.
    virtual void onCollisionEnter(const CollisionEvent& event);
    virtual void onCollisionStay(const CollisionEvent& event);
    virtual void onCollisionExit(const CollisionEvent& event);

    // A name for messages and the debugger ("coin 3"); empty by default, when messages say
    // where the object is instead.
    void setName(std::string newName);
    [[nodiscard]] const std::string& getName() const;
    // The name, or "the object at (x, y)" when it has none.
    [[nodiscard]] std::string describe() const;

    // In pixels per second. GameObject never moves itself: your update() does.
    void setVelocity(sf::Vector2f newVelocity);
    void setVelocity(float x, float y);
    [[nodiscard]] sf::Vector2f getVelocity() const;

    // A new object is alive and a collider. Collision checks ignore dead objects and
    // objects that are not colliders.
    [[nodiscard]] bool isAlive() const;
    void setAlive(bool isAliveNow);
    [[nodiscard]] bool isCollider() const;
    void setCollider(bool isColliderNow);

    // The collision box in world coordinates: the local box moved, scaled and rotated with
    // the object (when rotated: the smallest axis-aligned box around the turned box).
    [[nodiscard]] sf::FloatRect getCollisionBox() const;
    // The box relative to the object's position (its origin point), in unscaled pixels.
    void setCollisionBox(float left, float top, float width, float height);
    void setCollisionBox(const sf::FloatRect& box);
    // Go back to "the box is the whole shape".
    void clearCollisionBox();
    // The local box: the one set, or the whole shape measured from the origin point.
    [[nodiscard]] sf::FloatRect getLocalCollisionBox() const;

    // The bounding circle in world coordinates. Default: the circle inscribed in the
    // collision box (centre of the box, radius half its shorter side, after scaling; a
    // circle set with setBoundingCircle scales by the smaller of the two scales).
    [[nodiscard]] Circle getBoundingCircle() const;
    // A circle measured from the object's position (its origin point), like the box.
    void setBoundingCircle(sf::Vector2f centerFromOrigin, float radius);
    // Go back to the default circle (inscribed in the collision box).
    void clearBoundingCircle();

protected:
    sf::Vector2f velocity;
    bool alive = true;
    bool collider = true;

    // The box every query reads, relative to the origin point: the one setCollisionBox gave,
    // or none (the whole shape). Virtual so that a class keeping a box of its own can answer
    // with it: the course's GameObjects (framework/compat/) read the member old lab code assigns.
    [[nodiscard]] virtual std::optional<Box> givenCollisionBox() const;

private:
    friend class World;        // keeps `worlds` up to date
    mutable WorldLinks worlds; // the Worlds this object is in (empty in a copy)
    Box localBox;              // relative to the origin point; read only while hasBox
    bool hasBox = false;
    std::string name;
    bool hasOwnCircle = false; // false: the circle inscribed in the collision box
    sf::Vector2f circleCenter; // relative to the origin point
    float circleRadius = 0.f;
};

} // namespace hitbox
