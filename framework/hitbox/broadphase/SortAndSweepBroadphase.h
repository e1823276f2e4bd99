// SortAndSweepBroadphase.h - sort the boxes by their left edge, then sweep (Ericson,
// Real-Time Collision Detection, 7.5: only boxes whose spans meet along x can touch).
//
// After sorting by left edge, box i can only overlap the boxes that come after it while their
// left edge is still left of i's right edge: the sweep stops there. Objects move a little
// each frame, so last frame's order is almost right: insertion sort fixes it in about n steps
// (temporal coherence). If objects jump far, it falls back to a full sort.
#pragma once

#include "hitbox/broadphase/BoxArrays.h"
#include "hitbox/broadphase/Broadphase.h"

namespace hitbox
{

class SortAndSweepBroadphase : public Broadphase
{
public:
    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override;
    [[nodiscard]] const char* name() const override { return "SortAndSweep"; }
    [[nodiscard]] BroadphaseStats stats() const override { return lastStats; }
    // Each box's x range, in sweep order.
    [[nodiscard]] BroadphaseLayout layout() const override;

private:
    void sortByLeftEdge();

    BoxArrays boxes;
    std::vector<std::uint32_t> order; // item indices sorted by minX, kept between frames
    BroadphaseStats lastStats;
};

} // namespace hitbox
