// TimelineStrip.h - the rewind strip along the bottom of a paused window: the kept steps from
// left (oldest) to right (newest), a tick for every contact that began (enter: tall, vermillion)
// or ended (exit: short, sky blue) and a white bar at the step shown. Drawn from plain data
// (the window hands it the timeline's enters and exits, app/Timeline.h); click it to jump.
#pragma once

#include "hitbox/geometry/Shapes.h"

#include <vector>

namespace sf
{
class RenderTarget;
}

namespace hitbox
{

struct StripMark
{
    long long step = 0;
    bool enter = true; // false: an exit
};

struct StripRange
{
    long long oldest = 0; // the left edge
    long long newest = 0; // the right edge
    long long shown = 0;  // the white bar
};

// Where `step` is drawn in `area`: oldest at its left edge, newest at its right (a range of one
// step: the middle). Steps outside the range are clamped to the edges.
[[nodiscard]] float stripXOf(const Box& area, StripRange range, long long step);
// The step drawn nearest to `x`, clamped to the range: what a click at `x` jumps to.
[[nodiscard]] long long stripStepAt(const Box& area, StripRange range, float x);

// Draws the strip into `area` (world coordinates) with the marks inside the range.
void drawTimelineStrip(sf::RenderTarget& target, const Box& area, StripRange range,
                       const std::vector<StripMark>& marks);

} // namespace hitbox
