#include "Framework/GameObject.h"

#include "hitbox/sfml/Conversions.h"

GameObject::GameObject()
{
    setCollider(false);
}

GameObject::GameObject(const GameObject& other)
    : hitbox::GameObject(other), m_collisionBox(other.m_collisionBox), m_input(other.m_input),
      m_window(other.m_window)
{
}

GameObject& GameObject::operator=(const GameObject& other)
{
    hitbox::GameObject::operator=(other); // the state m_velocity, m_alive, m_collider name
    m_collisionBox = other.m_collisionBox;
    m_input = other.m_input;
    m_window = other.m_window;
    return *this;
}

void GameObject::collisionResponse(GameObject&) {}

void GameObject::collisionResponse(hitbox::GameObject* other)
{
    if (auto* courseObject = dynamic_cast<GameObject*>(other))
        collisionResponse(*courseObject);
}

void GameObject::setCollisionBox(float x, float y, float width, float height)
{
    m_collisionBox = sf::FloatRect({x, y}, {width, height});
}

void GameObject::setCollisionBox(sf::FloatRect box)
{
    m_collisionBox = box;
}

std::optional<hitbox::Box> GameObject::givenCollisionBox() const
{
    if (m_collisionBox.size.x == 0.f && m_collisionBox.size.y == 0.f)
        return std::nullopt;
    return hitbox::toBox(m_collisionBox);
}

void GameObject::setInput(Input* input)
{
    m_input = input;
}

void GameObject::setWindow(sf::RenderWindow* window)
{
    m_window = window;
}
