#include "hitbox/objects/GameObject.h"

#include "hitbox/objects/World.h"

#include <cmath>
#include <sstream>
#include <utility>

hitbox::OptionalBox& hitbox::OptionalBox::operator=(const sf::FloatRect& box)
{
    sf::FloatRect::operator=(box);
    isSet = true;
    return *this;
}

GameObject::GameObject() = default;

GameObject::~GameObject()
{
    for (hitbox::World* world : worlds.worlds())
        world->forgetDestroyed(*this);
}

void GameObject::handleInput(float) {}

void GameObject::update(float) {}

void GameObject::collisionResponse(GameObject*) {}

void GameObject::onCollisionEnter(const hitbox::CollisionEvent&) {}

void GameObject::onCollisionStay(const hitbox::CollisionEvent&) {}

void GameObject::onCollisionExit(const hitbox::CollisionEvent&) {}

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
    collisionBox = sf::FloatRect({left, top}, {width, height});
}

void GameObject::setCollisionBox(const sf::FloatRect& box)
{
    collisionBox = box;
}

void GameObject::clearCollisionBox()
{
    collisionBox = hitbox::OptionalBox();
}

sf::FloatRect GameObject::getLocalCollisionBox() const
{
    if (collisionBox.isSet)
        return collisionBox;
    const sf::Vector2f origin = getOrigin();
    return sf::FloatRect({-origin.x, -origin.y}, getSize());
}

// [slide:collision-box-world]
sf::FloatRect GameObject::getCollisionBox() const
{
    // The box is measured from the origin point; the shape's own coordinates start at its
    // top-left corner, so shift by the origin before applying the object's transform.
    hitbox::Box box = hitbox::normalised(hitbox::toBox(getLocalCollisionBox()));
    box.left += getOrigin().x;
    box.top += getOrigin().y;
    return getTransform().transformRect(hitbox::toSfml(box));
}
// [/slide]

// [slide:bounding-circle-radius]
hitbox::Circle GameObject::getBoundingCircle() const
{
    const sf::Vector2f scale(std::fabs(getScale().x), std::fabs(getScale().y));
    if (hasOwnCircle) // a circle stretched one way is an ellipse: keep the one inside it
        return {hitbox::toVec2(getTransform().transformPoint(circleCenter + getOrigin())),
                circleRadius * std::fmin(scale.x, scale.y)};
    // The circle inscribed in the (scaled) collision box: the fix for the old framework,
    // which took the radius from the shape's width and the centre from its top-left corner.
    const hitbox::Box box = hitbox::normalised(hitbox::toBox(getLocalCollisionBox()));
    const float radius = std::fmin(box.width * scale.x, box.height * scale.y) / 2.f;
    const sf::Vector2f center = hitbox::toSfml(hitbox::centerOf(box)) + getOrigin();
    return {hitbox::toVec2(getTransform().transformPoint(center)), radius};
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

void GameObject::setInput(Input* newInput)
{
    input = newInput;
}

void GameObject::setWindow(sf::RenderWindow* newWindow)
{
    window = newWindow;
}
