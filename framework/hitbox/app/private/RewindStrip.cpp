#include "hitbox/app/private/RewindStrip.h"

#include "hitbox/debug/TimelineStrip.h"

#include <vector>

namespace hitbox
{

Box stripArea(sf::Vector2f world)
{
    return {8.f, world.y - 24.f - 26.f, world.x - 16.f, 22.f};
}

bool canRewind(const RewindTools& tools, bool paused)
{
    return paused && tools.rewind != nullptr && tools.rewind->canRewind();
}

void drawRewindStrip(sf::RenderTarget& target, sf::Vector2f world, const RewindTools& tools)
{
    const RewindLevel& rewind = *tools.rewind;
    std::vector<StripMark> marks;
    if (tools.timeline != nullptr)
        for (const TimelineEvent& event : tools.timeline->getEvents())
            if (event.kind != ContactPhase::Stay && event.step >= rewind.oldestStep())
                marks.push_back({event.step, event.kind == ContactPhase::Enter});
    drawTimelineStrip(target, stripArea(world),
                      {rewind.oldestStep(), rewind.newestStep(), rewind.shownStep()}, marks);
}

long long stepForKey(long long from, sf::Keyboard::Key key)
{
    if (key == sf::Keyboard::Key::Left)
        return from - 1;
    if (key == sf::Keyboard::Key::Right)
        return from + 1;
    return from;
}

long long stepForClick(const RewindLevel& rewind, sf::Vector2f world, sf::Vector2f at)
{
    const Box area = stripArea(world);
    if (at.y < area.top || at.y > area.top + area.height)
        return -1;
    return stripStepAt(area, {rewind.oldestStep(), rewind.newestStep(), rewind.shownStep()}, at.x);
}

} // namespace hitbox
