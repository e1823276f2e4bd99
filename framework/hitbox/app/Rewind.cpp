#include "hitbox/app/Rewind.h"

#include "hitbox/app/Input.h"

#include <algorithm>
#include <utility>

namespace hitbox
{

RewindLevel::RewindLevel(Level& inner, long long keptSteps, long long snapshotSteps)
    : WrappedLevel(inner), keptSteps(std::max(1LL, keptSteps)),
      snapshotSteps(std::max(1LL, snapshotSteps))
{
    snapshot();
}

RewindLevel::RewindLevel(Level& inner, LevelMaker remake, long long keptSteps,
                         long long snapshotSteps, long long rebuildSteps)
    : RewindLevel(inner, keptSteps, snapshotSteps)
{
    this->rebuildSteps = rebuildSteps;
    if (snapshots.empty() && remake)
        replayed = std::make_unique<ReplayedRun>(std::move(remake));
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
    if (replayed && step >= rebuildSteps)
    {
        replayed.reset(); // the memory bound (rewindRebuildSteps): no rewind from here on
        rebuilt = nullptr;
    }
    if (replayed)
        replayed->addStep(captureInput(input));
    else if (canRewind())
        inputs.push_back(captureInput(input));
    inner.handleInput(input, dt);
}

void RewindLevel::update(float dt)
{
    WrappedLevel::update(dt);
    shown = step;
    if (snapshots.empty())
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
    if (replayed)
        return std::max(0LL, step - keptSteps);
    return canRewind() ? std::max(snapshots.front().first, step - keptSteps) : step;
}

long long RewindLevel::show(long long wanted)
{
    wanted = std::clamp(wanted, oldestStep(), step);
    if (wanted == shown || !canRewind())
        return shown;
    if (replayed)
    {
        // The live level stays as it is: an earlier step is shown by a rebuilt one.
        rebuilt = wanted == step ? nullptr : &replayed->levelAt(wanted);
        if (!rebuilt)
            replayed->forget();
        return shown = wanted;
    }
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
        ++resimulated;
    }
    return shown;
}

long long RewindLevel::stepsReplayed() const
{
    return resimulated + (replayed ? replayed->stepsReplayed() : 0);
}

const Level& RewindLevel::shownLevel() const
{
    return rebuilt != nullptr ? *rebuilt : inner;
}

void RewindLevel::render(sf::RenderTarget& target) const
{
    shownLevel().render(target);
}

void RewindLevel::renderBlended(sf::RenderTarget& target, float leftover) const
{
    shownLevel().renderBlended(target, leftover);
}

void RewindLevel::renderDebug(DebugRenderer& debug) const
{
    shownLevel().renderDebug(debug);
}

std::string RewindLevel::getHelpText() const
{
    return shownLevel().getHelpText();
}

std::string RewindLevel::describeState() const
{
    return shownLevel().describeState();
}

std::vector<PairEvent> RewindLevel::getContactEvents() const
{
    return shownLevel().getContactEvents();
}

std::size_t RewindLevel::bytesUsed() const
{
    std::size_t bytes = replayed ? replayed->bytesUsed() : 0;
    for (const auto& [at, state] : snapshots)
        bytes += state->bytes() + sizeof(at);
    for (const InputSnapshot& input : inputs)
        bytes += sizeof(InputSnapshot) +
                 sizeof(int) * (input.keysDown.capacity() + input.keysPressed.capacity() +
                                input.keysReleased.capacity());
    return bytes;
}

} // namespace hitbox
