#include "TimedBroadphase.h"

#include "hitbox/broadphase/GridBroadphase.h"
#include "hitbox/platform/Platform.h"

#include <utility>

TimedBroadphase::TimedBroadphase(std::unique_ptr<hitbox::Broadphase> measured)
    : inner(std::move(measured))
{
}

void TimedBroadphase::findPairs(const std::vector<hitbox::BroadphaseItem>& items,
                                std::vector<hitbox::Pair>& pairs)
{
    const double begin = hitbox::platform::threadCpuSeconds();
    inner->findPairs(items, pairs);
    const auto* grid = dynamic_cast<const hitbox::GridBroadphase*>(inner.get());
    workerExtra = grid != nullptr ? grid->lastWorkerExtraSeconds() : 0.0;
    seconds = hitbox::platform::threadCpuSeconds() - begin + workerExtra;
}
