// ExplainPair.h - explain(a, b): why two GameObjects do or do not collide, in words, the way
// Collision and World test them (geometry/Explain.h does the shapes).
//
//     std::cout << hitbox::toText(hitbox::explain(ball, paddle)) << "\n";
//     // 'ball' and 'paddle' do not collide: on y they are apart
//     //   x: 'ball' [100, 110] and 'paddle' [95, 115] overlap by 10
//     //   y: 'ball' [40, 50] and 'paddle' [60, 140] are 10 apart
#pragma once

#include "hitbox/geometry/Explain.h"
#include "hitbox/objects/World.h"

namespace hitbox
{
class GameObject;

// The objects' names are used when set (GameObject::setName), else "A" and "B". A dead
// object, one that is not a collider, or an object against itself never collides, and the
// verdict says which. Box against Box: their collision boxes; Circle: the bounding circle.
// Another kind of `shapes` (docs/adding-a-shape.md) has no words yet: `collides` is then the
// table's test's answer, and the verdict says so and that it has no explanation.
[[nodiscard]] Explanation explain(const GameObject& a, const GameObject& b,
                                  World::Shape shapeA = World::Shape::Box,
                                  World::Shape shapeB = World::Shape::Box,
                                  const ShapeTable& shapes = ShapeTable::standard());

} // namespace hitbox
