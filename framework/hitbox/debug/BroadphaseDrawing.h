// BroadphaseDrawing.h - draws what a broadphase built (its BroadphaseLayout): the grid and its
// busy cells, the quadtree's nodes, or the sorted x ranges of sort and sweep.
#pragma once

#include "hitbox/broadphase/Broadphase.h"
#include "hitbox/debug/DebugRenderer.h"

namespace hitbox
{

// Grid lines (up to 400 by 400 cells; hairlines for cells under 24 units, else 2 units wide) and
// the cells holding two or more boxes (up to 20,000 cells); every quadtree node; each sweep
// interval as a bar along the top of the world.
void drawBroadphase(DebugRenderer& debug, const BroadphaseLayout& layout);

} // namespace hitbox
