// ExplainOverlay.h - the debug view's answer to "why did these two (not) collide?": the pair
// under the mouse, or else the last pair whose contact began or ended, explained in the F1
// panel (objects/ExplainPair.h) with both shapes outlined.
#pragma once

#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/objects/World.h"

namespace hitbox
{

// Explains the pair of `world`'s objects whose collision boxes hold `mouse` (world
// coordinates; the first two found, in the order added), or when fewer than two do, the
// world's last change (World::getLastChange). Draws nothing when there is no such pair or
// one of the two was destroyed. Outlines both shapes in DebugRenderer::hintColor.
void explainInPanel(DebugRenderer& debug, const World& world, Vec2 mouse,
                    const std::vector<const GameObject*>& objects);

} // namespace hitbox
