#include "Framework/GameObject.h"

#include "hitbox/sfml/Conversions.h"

GameObject::AssignedBox& GameObject::AssignedBox::operator=(const sf::FloatRect& box)
{
    sf::FloatRect::operator=(box);
    isSet = true;
    return *this;
}

void GameObject::collisionResponse(GameObject*) {}

void GameObject::collisionResponse(hitbox::GameObject* other)
{
    collisionResponse(dynamic_cast<GameObject*>(other));
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
    collisionBox = AssignedBox();
    hitbox::GameObject::clearCollisionBox();
}

std::optional<hitbox::Box> GameObject::givenCollisionBox() const
{
    if (collisionBox.isSet)
        return hitbox::toBox(collisionBox);
    return hitbox::GameObject::givenCollisionBox(); // one set through Hitbox's own setter
}

void GameObject::setInput(Input* newInput)
{
    input = newInput;
}

void GameObject::setWindow(sf::RenderWindow* newWindow)
{
    window = newWindow;
}
