// BruteForceBroadphase.h - test every pair: all n(n-1)/2 of them.
//
// Always right and simple enough to trust, so the tests compare every other method with it.
// Fine for a few hundred objects; at 10,000 it runs 50 million tests a frame.
#pragma once

#include "hitbox/broadphase/BoxArrays.h"
#include "hitbox/broadphase/Broadphase.h"

namespace hitbox
{

class BruteForceBroadphase : public Broadphase
{
public:
    void findPairs(const std::vector<BroadphaseItem>& items, std::vector<Pair>& pairs) override;
    [[nodiscard]] const char* name() const override { return "BruteForce"; }
    [[nodiscard]] BroadphaseStats stats() const override { return lastStats; }

private:
    BoxArrays boxes;
    BroadphaseStats lastStats;
};

} // namespace hitbox
