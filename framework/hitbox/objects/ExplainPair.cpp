#include "hitbox/objects/ExplainPair.h"

#include "hitbox/objects/GameObject.h"

#include <string>

namespace hitbox
{
namespace
{

std::string nameOf(const GameObject& object, const char* fallback)
{
    return object.getName().empty() ? std::string(fallback) : "'" + object.getName() + "'";
}

} // namespace

Explanation explain(const GameObject& a, const GameObject& b, World::Shape shapeA,
                    World::Shape shapeB, const ShapeTable& shapes)
{
    const std::string nameA = nameOf(a, "A");
    const std::string nameB = nameOf(b, "B");
    Explanation why;
    // Collision.h's rules for objects that cannot collide, before any shape is looked at.
    if (&a == &b)
        why.verdict = nameA + " does not collide with itself";
    for (const GameObject* object : {&a, &b})
    {
        if (!why.verdict.empty())
            break;
        const std::string& name = object == &a ? nameA : nameB;
        if (!object->isAlive())
            why.verdict =
                nameA + " and " + nameB + " do not collide: " + name + " is dead (setAlive(false))";
        else if (!object->isCollider())
            why.verdict = nameA + " and " + nameB + " do not collide: " + name +
                          " is not a collider (setCollider(false))";
    }
    if (!why.verdict.empty())
        return why;
    // The explanations are written for Hitbox's own kinds; a kind added to a ShapeTable
    // (docs/adding-a-shape.md) gets the table's answer and this line until it has words of
    // its own, never a reason that is not the test's.
    for (const World::Shape kind : {shapeA, shapeB})
        if (kind != World::Shape::Box && kind != World::Shape::Circle)
        {
            why.collides = shapes.test(a, shapeA, b, shapeB).hit;
            why.verdict =
                nameA + " and " + nameB + (why.collides ? " collide" : " do not collide") +
                " (the " + shapes.nameOf(shapeA) + "-" + shapes.nameOf(shapeB) +
                " test says so); no explanation for shape kind " +
                std::to_string(static_cast<int>(kind)) + " (only box and circle are explained)";
            return why;
        }
    const Box boxA = toBox(a.getCollisionBox());
    const Box boxB = toBox(b.getCollisionBox());
    if (shapeA == World::Shape::Box && shapeB == World::Shape::Box)
        return explainBoxes(boxA, boxB, nameA, nameB);
    if (shapeA == World::Shape::Circle && shapeB == World::Shape::Circle)
        return explainCircles(a.getBoundingCircle(), b.getBoundingCircle(), nameA, nameB);
    if (shapeA == World::Shape::Circle)
        return explainCircleBox(a.getBoundingCircle(), boxB, nameA, nameB);
    return explainCircleBox(b.getBoundingCircle(), boxA, nameB, nameA);
}

} // namespace hitbox
