// GameObject.h - a rectangle shape that moves and collides.
//
// The base class of every object in the labs and in Pong, and the same API as the course's
// old Framework/GameObject.h (so old lab code builds unchanged). What changed from the old
// framework is listed in docs/course-labs.md ("Differences from the course's framework").
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

#include <string>

namespace sf
{
class RenderWindow;
}
class Input;

namespace hitbox
{
class World;
// A collision box relative to the origin point, and whether one was given. Old lab code
// assigns the box directly (`collisionBox = sf::FloatRect(...)`): that counts as given too.
// Until then it reads as {0, 0, 0, 0}, as in the course's old framework.
struct OptionalBox : sf::FloatRect
{
    bool isSet = false;

    OptionalBox& operator=(const sf::FloatRect& box);
};
} // namespace hitbox

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
    virtual void onCollisionEnter(const hitbox::CollisionEvent& event);
    virtual void onCollisionStay(const hitbox::CollisionEvent& event);
    virtual void onCollisionExit(const hitbox::CollisionEvent& event);

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
    [[nodiscard]] hitbox::Circle getBoundingCircle() const;
    // A circle measured from the object's position (its origin point), like the box.
    void setBoundingCircle(sf::Vector2f centerFromOrigin, float radius);
    // Go back to the default circle (inscribed in the collision box).
    void clearBoundingCircle();

    // The course framework hands every object the input and the window it may use.
    void setInput(Input* newInput);
    void setWindow(sf::RenderWindow* newWindow);

protected:
    sf::Vector2f velocity;
    bool alive = true;
    // Relative to the origin point. Not set (isSet false): the whole shape is used.
    hitbox::OptionalBox collisionBox;
    bool collider = true;
    Input* input = nullptr;
    sf::RenderWindow* window = nullptr;

private:
    friend class hitbox::World;        // keeps `worlds` up to date
    mutable hitbox::WorldLinks worlds; // the Worlds this object is in (empty in a copy)
    std::string name;
    bool hasOwnCircle = false; // false: the circle inscribed in the collision box
    sf::Vector2f circleCenter; // relative to the origin point
    float circleRadius = 0.f;
};
