// TimedBroadphase.h - a broadphase that measures itself: it passes every call to the real one
// and keeps the CPU seconds the last findPairs took (with a two-thread grid: the calling
// thread's time plus what the second thread spent beyond it). Lab 8 wraps its broadphase in
// one so --print-timing can say how much of a step the broadphase was, without touching the
// code students write.
#pragma once

#include "hitbox/broadphase/Broadphase.h"

#include <memory>
#include <vector>

class TimedBroadphase : public hitbox::Broadphase
{
public:
    explicit TimedBroadphase(std::unique_ptr<hitbox::Broadphase> measured);

    void findPairs(const std::vector<hitbox::BroadphaseItem>& items,
                   std::vector<hitbox::Pair>& pairs) override;
    const char* name() const override { return inner->name(); }
    hitbox::BroadphaseStats stats() const override { return inner->stats(); }
    hitbox::BroadphaseLayout layout() const override { return inner->layout(); }

    // CPU seconds of the last findPairs (0 before the first).
    [[nodiscard]] double lastSeconds() const { return seconds; }
    // Of those, what a second thread spent beyond the calling thread (0 with one thread):
    // not in the calling thread's own CPU time, so the step adds it.
    [[nodiscard]] double lastWorkerExtraSeconds() const { return workerExtra; }

private:
    std::unique_ptr<hitbox::Broadphase> inner;
    double seconds = 0.0;
    double workerExtra = 0.0;
};
