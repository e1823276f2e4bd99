#include "hitbox/debug/TimelineStrip.h"

#include "hitbox/debug/DebugRenderer.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <algorithm>
#include <cmath>

namespace hitbox
{
namespace
{

void bar(sf::RenderTarget& target, float left, float top, float width, float height,
         sf::Color color)
{
    sf::RectangleShape shape({width, height});
    shape.setPosition({left, top});
    shape.setFillColor(color);
    target.draw(shape);
}

} // namespace

float stripXOf(const Box& area, StripRange range, long long step)
{
    if (range.newest <= range.oldest)
        return area.left + area.width / 2.f;
    const long long clamped = std::clamp(step, range.oldest, range.newest);
    const double fraction = static_cast<double>(clamped - range.oldest) /
                            static_cast<double>(range.newest - range.oldest);
    return area.left + static_cast<float>(fraction) * area.width;
}

long long stripStepAt(const Box& area, StripRange range, float x)
{
    if (range.newest <= range.oldest || !(area.width > 0.f))
        return range.newest;
    const double fraction = std::clamp((x - area.left) / area.width, 0.f, 1.f);
    return range.oldest + std::llround(fraction * static_cast<double>(range.newest - range.oldest));
}

void drawTimelineStrip(sf::RenderTarget& target, const Box& area, StripRange range,
                       const std::vector<StripMark>& marks)
{
    bar(target, area.left, area.top, area.width, area.height, sf::Color(0, 0, 0, 200));
    for (const StripMark& mark : marks)
    {
        if (mark.step < range.oldest || mark.step > range.newest)
            continue;
        // Told apart by height as well as colour, so no one needs the colour.
        const float height = mark.enter ? area.height - 4.f : (area.height - 4.f) / 2.f;
        bar(target, stripXOf(area, range, mark.step) - 1.f, area.top + area.height - 2.f - height,
            2.f, height, mark.enter ? DebugRenderer::overlappingColor : DebugRenderer::freeColor);
    }
    bar(target, stripXOf(area, range, range.shown) - 1.5f, area.top, 3.f, area.height,
        sf::Color::White);
}

} // namespace hitbox
