#include "hitbox/debug/ExplainOverlay.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/objects/ExplainPair.h"
#include "hitbox/objects/GameObject.h"

namespace hitbox
{

void explainInPanel(DebugRenderer& debug, const World& world, Vec2 mouse,
                    const std::vector<const GameObject*>& objects)
{
    const GameObject* first = nullptr;
    const GameObject* second = nullptr;
    for (const GameObject* object : objects)
    {
        if (object == nullptr || !world.contains(*object) ||
            !pointInBox(mouse, toBox(object->getCollisionBox())))
            continue;
        (first == nullptr ? first : second) = object;
        if (second != nullptr)
            break;
    }
    if (second == nullptr)
    {
        first = world.getLastChange().first;
        second = world.getLastChange().second;
    }
    if (first == nullptr || second == nullptr)
        return;
    const Explanation why = explain(*first, *second, world.getShape(*first),
                                    world.getShape(*second), world.getShapes());
    std::vector<std::string> lines{why.verdict};
    for (const std::string& step : why.steps)
        lines.push_back("  " + step);
    debug.panel(lines);
    debug.box(toBox(first->getCollisionBox()), DebugRenderer::hintColor);
    debug.box(toBox(second->getCollisionBox()), DebugRenderer::hintColor);
}

} // namespace hitbox
