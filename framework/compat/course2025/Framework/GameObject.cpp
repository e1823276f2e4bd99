#include "Framework/GameObject.h"

#include "hitbox/sfml/Conversions.h"

void GameObject::handleInput(float) {}

void GameObject::update(float) {}

void GameObject::collisionResponse(GameObject&) {}

void GameObject::setVelocity(sf::Vector2f velocity)
{
    m_velocity = velocity;
}

void GameObject::setVelocity(float x, float y)
{
    m_velocity = {x, y};
}

sf::Vector2f GameObject::getVelocity() const
{
    return m_velocity;
}

bool GameObject::isAlive() const
{
    return m_alive;
}

void GameObject::setAlive(bool alive)
{
    m_alive = alive;
}

bool GameObject::isCollider() const
{
    return m_collider;
}

void GameObject::setCollider(bool collider)
{
    m_collider = collider;
}

sf::FloatRect GameObject::getCollisionBox() const
{
    // The local box is measured from the origin point; the shape's own coordinates are
    // measured from its top-left corner, where the origin point sits at getOrigin().
    // A negative size spans backwards, as Hitbox's boxes do (hitbox::normalised).
    const bool boxSet = m_collisionBox.size.x != 0.f || m_collisionBox.size.y != 0.f;
    hitbox::Box local = hitbox::toBox(getLocalBounds());
    if (boxSet)
    {
        local = hitbox::normalised(hitbox::toBox(m_collisionBox));
        local.left += getOrigin().x;
        local.top += getOrigin().y;
    }
    return getTransform().transformRect(hitbox::toSfml(local));
}

void GameObject::setCollisionBox(float x, float y, float width, float height)
{
    m_collisionBox = sf::FloatRect({x, y}, {width, height});
}

void GameObject::setCollisionBox(sf::FloatRect box)
{
    m_collisionBox = box;
}

void GameObject::setInput(Input* input)
{
    m_input = input;
}

void GameObject::setWindow(sf::RenderWindow* window)
{
    m_window = window;
}
