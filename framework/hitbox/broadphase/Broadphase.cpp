#include "hitbox/broadphase/Broadphase.h"

#include "hitbox/broadphase/BruteForceBroadphase.h"
#include "hitbox/broadphase/GridBroadphase.h"
#include "hitbox/broadphase/QuadtreeBroadphase.h"
#include "hitbox/broadphase/SortAndSweepBroadphase.h"

namespace hitbox
{

std::unique_ptr<Broadphase> makeBroadphase(BroadphaseMethod method)
{
    switch (method)
    {
    case BroadphaseMethod::BruteForce:
        return std::make_unique<BruteForceBroadphase>();
    case BroadphaseMethod::SortAndSweep:
        return std::make_unique<SortAndSweepBroadphase>();
    case BroadphaseMethod::Quadtree:
        return std::make_unique<QuadtreeBroadphase>();
    case BroadphaseMethod::Grid:
        break;
    }
    // The grid picks its cell size from the boxes each frame.
    return std::make_unique<GridBroadphase>();
}

const char* toString(BroadphaseMethod method)
{
    switch (method)
    {
    case BroadphaseMethod::BruteForce:
        return "BruteForce";
    case BroadphaseMethod::SortAndSweep:
        return "SortAndSweep";
    case BroadphaseMethod::Grid:
        return "Grid";
    case BroadphaseMethod::Quadtree:
        return "Quadtree";
    }
    return "Unknown";
}

} // namespace hitbox
