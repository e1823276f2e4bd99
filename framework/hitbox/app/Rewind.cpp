#include "hitbox/app/Rewind.h"

#include "hitbox/app/Input.h"

#include <algorithm>

namespace hitbox
{

RewindLevel::RewindLevel(Level& inner, long long keptSteps, long long snapshotSteps)
    : WrappedLevel(inner), keptSteps(std::max(1LL, keptSteps)),
      snapshotSteps(std::max(1LL, snapshotSteps))
{
    snapshot();
}

void RewindLevel::snapshot()
{
    std::unique_ptr<LevelState> state = inner.saveState();
    if (state)
        snapshots.emplace_back(step, std::move(state));
}

void RewindLevel::handleInput(const Input& input, float dt)
{
    show(step); // a live step starts from the newest state, never from a rewound one
    if (canRewind())
        inputs.push_back(captureInput(input));
    inner.handleInput(input, dt);
}

void RewindLevel::update(float dt)
{
    WrappedLevel::update(dt);
    shown = step;
    if (!canRewind())
        return;
    if (step % snapshotSteps == 0)
        snapshot();
    // Drop what is older than needed: keep the last snapshot at or before step - keptSteps.
    while (snapshots.size() > 1 && snapshots[1].first <= step - keptSteps)
        snapshots.pop_front();
    while (firstInput < snapshots.front().first)
    {
        inputs.pop_front();
        ++firstInput;
    }
}

long long RewindLevel::oldestStep() const
{
    return canRewind() ? std::max(snapshots.front().first, step - keptSteps) : step;
}

long long RewindLevel::show(long long wanted)
{
    wanted = std::clamp(wanted, oldestStep(), step);
    if (wanted == shown || !canRewind())
        return shown;
    // Forward from the shown step when that is on the way; else from the nearest snapshot.
    auto from = std::prev(std::upper_bound(snapshots.begin(), snapshots.end(), wanted,
                                           [](long long at, const auto& snapshot)
                                           { return at < snapshot.first; }));
    if (!(shown < wanted && shown >= from->first))
    {
        inner.restoreState(*from->second);
        shown = from->first;
    }
    for (; shown < wanted; ++shown)
    {
        inner.handleInput(restoreInput(inputs[static_cast<std::size_t>(shown - firstInput)]),
                          stepSeconds);
        inner.update(stepSeconds);
    }
    return shown;
}

std::size_t RewindLevel::bytesUsed() const
{
    std::size_t bytes = 0;
    for (const auto& [at, state] : snapshots)
        bytes += state->bytes() + sizeof(at);
    for (const InputSnapshot& input : inputs)
        bytes += sizeof(InputSnapshot) +
                 sizeof(int) * (input.keysDown.capacity() + input.keysPressed.capacity() +
                                input.keysReleased.capacity());
    return bytes;
}

} // namespace hitbox
