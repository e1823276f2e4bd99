#include "hitbox/objects/GameObject.h"

#include "hitbox/objects/World.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace hitbox
{

GameObject::GameObject() = default;

GameObject::~GameObject()
{
    for (World* world : worlds.worlds())
        world->forgetDestroyed(*this);
}

void GameObject::handleInput(float) {}

void GameObject::update(float) {}

void GameObject::collisionResponse(GameObject*) {}

void GameObject::onCollisionEnter(const CollisionEvent&) {}

void GameObject::onCollisionStay(const CollisionEvent&) {}

void GameObject::onCollisionExit(const CollisionEvent&) {}

void GameObject::setName(std::string newName)
{
    name = std::move(newName);
}

const std::string& GameObject::getName() const
{
    return name;
}

std::string GameObject::describe() const
{
    if (!name.empty())
        return "'" + name + "'";
    std::ostringstream text;
    text << "the object at (" << getPosition().x << ", " << getPosition().y << ")";
    return text.str();
}

void GameObject::setVelocity(sf::Vector2f newVelocity)
{
    velocity = newVelocity;
}

void GameObject::setVelocity(float x, float y)
{
    velocity = {x, y};
}

sf::Vector2f GameObject::getVelocity() const
{
    return velocity;
}

bool GameObject::isAlive() const
{
    return alive;
}

void GameObject::setAlive(bool isAliveNow)
{
    alive = isAliveNow;
}

bool GameObject::isCollider() const
{
    return collider;
}

void GameObject::setCollider(bool isColliderNow)
{
    collider = isColliderNow;
}

void GameObject::setCollisionBox(float left, float top, float width, float height)
{
    localBox = {left, top, width, height};
    hasBox = true;
}

void GameObject::setCollisionBox(const sf::FloatRect& box)
{
    localBox = toBox(box);
    hasBox = true;
}

void GameObject::clearCollisionBox()
{
    hasBox = false;
}

std::optional<Box> GameObject::givenCollisionBox() const
{
    if (hasBox)
        return localBox;
    return std::nullopt;
}

sf::FloatRect GameObject::getLocalCollisionBox() const
{
    if (const std::optional<Box> given = givenCollisionBox())
        return toSfml(*given);
    const sf::Vector2f origin = getOrigin();
    return sf::FloatRect({-origin.x, -origin.y}, getSize());
}

// [slide:collision-box-world]
sf::FloatRect GameObject::getCollisionBox() const
{
    // The box is measured from the origin point; the shape's own coordinates start at its
    // top-left corner, so shift by the origin before applying the object's transform.
    Box box = normalised(toBox(getLocalCollisionBox()));
    box.left += getOrigin().x;
    box.top += getOrigin().y;
    return getTransform().transformRect(toSfml(box));
}
// [/slide]

// [slide:bounding-circle-radius]
Circle GameObject::getBoundingCircle() const
{
    const sf::Vector2f scale(std::fabs(getScale().x), std::fabs(getScale().y));
    if (hasOwnCircle) // a circle stretched one way is an ellipse: keep the one inside it
        return {toVec2(getTransform().transformPoint(circleCenter + getOrigin())),
                circleRadius * std::fmin(scale.x, scale.y)};
    // The circle inscribed in the (scaled) collision box: the fix for the old framework,
    // which took the radius from the shape's width and the centre from its top-left corner.
    const Box box = normalised(toBox(getLocalCollisionBox()));
    const float radius = std::fmin(box.width * scale.x, box.height * scale.y) / 2.f;
    const sf::Vector2f center = toSfml(centerOf(box)) + getOrigin();
    return {toVec2(getTransform().transformPoint(center)), radius};
}
// [/slide]

void GameObject::setBoundingCircle(sf::Vector2f centerFromOrigin, float radius)
{
    hasOwnCircle = true;
    circleCenter = centerFromOrigin;
    circleRadius = radius;
}

void GameObject::clearBoundingCircle()
{
    hasOwnCircle = false;
}

} // namespace hitbox
