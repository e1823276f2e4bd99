#include "hitbox/app/RewindReplay.h"

#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace hitbox
{

const Level& ReplayedRun::levelAt(long long step)
{
    if (!shown || shownStep > step)
    {
        shown = remake();
        if (!shown)
            throw std::logic_error("hitbox::ReplayedRun: the level maker gave no level");
        shownStep = 0;
    }
    // The loop's step (Loop.cpp): the input of that step, then the update. Each input row is
    // turned into an Input once, when its step comes (restoreInput tries every key: slow next
    // to a small level's step).
    const auto& rows = inputs.changes;
    auto next = std::upper_bound(rows.begin(), rows.end(), shownStep,
                                 [](long long at, const auto& row) { return at < row.first; });
    Input input = restoreInput(next == rows.begin() ? InputSnapshot{} : std::prev(next)->second);
    for (; shownStep < step; ++shownStep, ++replayed)
    {
        if (next != rows.end() && next->first == shownStep)
            input = restoreInput((next++)->second);
        shown->handleInput(input, stepSeconds);
        shown->update(stepSeconds);
    }
    return *shown;
}

std::size_t ReplayedRun::bytesUsed() const
{
    std::size_t bytes = sizeof(Recording);
    for (const auto& [at, input] : inputs.changes)
        bytes += sizeof(at) + sizeof(InputSnapshot) +
                 sizeof(int) * (input.keysDown.capacity() + input.keysPressed.capacity() +
                                input.keysReleased.capacity());
    return bytes + (inputs.changes.capacity() - inputs.changes.size()) *
                       sizeof(std::pair<long long, InputSnapshot>);
}

} // namespace hitbox
