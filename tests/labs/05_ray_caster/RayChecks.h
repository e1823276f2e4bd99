// Helpers of lab 5's grading tests: stepping the level with the mouse aimed, the check that the
// player is in no solid, tiled floors and walls, and the speed of a diagonal move. Both the
// grading tests (RayGradingTests.cpp) and their hidden variants use them: one home for each.
#pragma once

#include "RayLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/sfml/Conversions.h"

#include <cmath>
#include <vector>

namespace raychecks
{

// Each axis of a diagonal move at the player's 300 px/s: what a slide keeps if it never slows.
inline const float diagonalSpeed = 300.f / std::sqrt(2.f);

// Steps the level `steps` times as the window does, the mouse at `mouse` and no key pressed.
inline void runWithMouse(RayLevel& level, hitbox::Vec2 mouse, int steps)
{
    hitbox::Input input;
    input.setMousePosition(hitbox::toSfml(mouse));
    for (int step = 0; step < steps; ++step)
    {
        level.handleInput(input, hitbox::stepSeconds);
        level.update(hitbox::stepSeconds);
        input.update();
    }
}

// Whether the player has got into a solid: the one thing a move and slide must never allow.
inline bool overlapsAnySolid(const RayLevel& level)
{
    for (const hitbox::Box& solid : level.getSolids())
        if (hitbox::boxVsBox(hitbox::toBox(level.getPlayer().getCollisionBox()), solid))
            return true;
    return false;
}

// A floor or wall of `count` separate 40-px tiles from `first`, `step` apart: seams to snag on.
inline std::vector<hitbox::Box> tileLine(hitbox::Vec2 first, hitbox::Vec2 step, int count)
{
    std::vector<hitbox::Box> tiles;
    for (int i = 0; i < count; ++i)
    {
        const hitbox::Vec2 corner = first + step * static_cast<float>(i);
        tiles.push_back({corner.x, corner.y, 40.f, 40.f});
    }
    return tiles;
}

} // namespace raychecks
