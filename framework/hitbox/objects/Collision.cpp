#include "hitbox/objects/Collision.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/objects/GameObject.h"

namespace hitbox
{

namespace
{

bool canCollide(const hitbox::GameObject* object)
{
    return object != nullptr && object->isAlive() && object->isCollider();
}

bool canCollide(const hitbox::GameObject* first, const hitbox::GameObject* second)
{
    return first != second && canCollide(first) && canCollide(second);
}

} // namespace

// [slide:collision-facade]
bool Collision::checkBoundingCircle(hitbox::GameObject* first, hitbox::GameObject* second)
{
    return canCollide(first, second) &&
           hitbox::circleVsCircle(first->getBoundingCircle(), second->getBoundingCircle());
}

bool Collision::checkBoundingBox(hitbox::GameObject* first, hitbox::GameObject* second)
{
    return canCollide(first, second) && hitbox::boxVsBox(hitbox::toBox(first->getCollisionBox()),
                                                         hitbox::toBox(second->getCollisionBox()));
}
// [/slide]

bool Collision::checkBoundingBox(hitbox::GameObject* object, sf::Vector2f point)
{
    return canCollide(object) &&
           hitbox::pointInBox(hitbox::toVec2(point), hitbox::toBox(object->getCollisionBox()));
}

bool Collision::checkBoundingBox(hitbox::GameObject* object, sf::Vector2i point)
{
    return checkBoundingBox(object, sf::Vector2f(point));
}

bool Collision::checkCircleBox(hitbox::GameObject* circleObject, hitbox::GameObject* boxObject)
{
    return canCollide(circleObject, boxObject) &&
           hitbox::circleVsBox(circleObject->getBoundingCircle(),
                               hitbox::toBox(boxObject->getCollisionBox()));
}

hitbox::Contact Collision::getBoundingCircleContact(hitbox::GameObject* first,
                                                    hitbox::GameObject* second)
{
    return getContact(first, hitbox::ShapeKind::Circle, second, hitbox::ShapeKind::Circle);
}

hitbox::Contact Collision::getBoundingBoxContact(hitbox::GameObject* first,
                                                 hitbox::GameObject* second)
{
    return getContact(first, hitbox::ShapeKind::Box, second, hitbox::ShapeKind::Box);
}

hitbox::Contact Collision::getCircleBoxContact(hitbox::GameObject* circleObject,
                                               hitbox::GameObject* boxObject)
{
    return getContact(circleObject, hitbox::ShapeKind::Circle, boxObject, hitbox::ShapeKind::Box);
}

hitbox::Contact Collision::getContact(hitbox::GameObject* first, hitbox::ShapeKind firstKind,
                                      hitbox::GameObject* second, hitbox::ShapeKind secondKind,
                                      const hitbox::ShapeTable& shapes)
{
    if (!canCollide(first, second))
        return {};
    return shapes.test(*first, firstKind, *second, secondKind);
}

} // namespace hitbox
