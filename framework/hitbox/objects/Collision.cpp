#include "hitbox/objects/Collision.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/objects/GameObject.h"

namespace
{

bool canCollide(const GameObject* object)
{
    return object != nullptr && object->isAlive() && object->isCollider();
}

bool canCollide(const GameObject* first, const GameObject* second)
{
    return first != second && canCollide(first) && canCollide(second);
}

} // namespace

// [slide:collision-facade]
bool Collision::checkBoundingCircle(GameObject* first, GameObject* second)
{
    return canCollide(first, second) &&
           hitbox::circleVsCircle(first->getBoundingCircle(), second->getBoundingCircle());
}

bool Collision::checkBoundingBox(GameObject* first, GameObject* second)
{
    return canCollide(first, second) && hitbox::boxVsBox(hitbox::toBox(first->getCollisionBox()),
                                                         hitbox::toBox(second->getCollisionBox()));
}
// [/slide]

bool Collision::checkBoundingBox(GameObject* object, sf::Vector2f point)
{
    return canCollide(object) &&
           hitbox::pointInBox(hitbox::toVec2(point), hitbox::toBox(object->getCollisionBox()));
}

bool Collision::checkBoundingBox(GameObject* object, sf::Vector2i point)
{
    return checkBoundingBox(object, sf::Vector2f(point));
}

bool Collision::checkCircleBox(GameObject* circleObject, GameObject* boxObject)
{
    return canCollide(circleObject, boxObject) &&
           hitbox::circleVsBox(circleObject->getBoundingCircle(),
                               hitbox::toBox(boxObject->getCollisionBox()));
}

hitbox::Contact Collision::getBoundingCircleContact(GameObject* first, GameObject* second)
{
    return getContact(first, hitbox::ShapeKind::Circle, second, hitbox::ShapeKind::Circle);
}

hitbox::Contact Collision::getBoundingBoxContact(GameObject* first, GameObject* second)
{
    return getContact(first, hitbox::ShapeKind::Box, second, hitbox::ShapeKind::Box);
}

hitbox::Contact Collision::getCircleBoxContact(GameObject* circleObject, GameObject* boxObject)
{
    return getContact(circleObject, hitbox::ShapeKind::Circle, boxObject, hitbox::ShapeKind::Box);
}

hitbox::Contact Collision::getContact(GameObject* first, hitbox::ShapeKind firstKind,
                                      GameObject* second, hitbox::ShapeKind secondKind,
                                      const hitbox::ShapeTable& shapes)
{
    if (!canCollide(first, second))
        return {};
    return shapes.test(*first, firstKind, *second, secondKind);
}
