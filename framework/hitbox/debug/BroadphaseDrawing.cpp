#include "hitbox/debug/BroadphaseDrawing.h"

#include <algorithm>

namespace hitbox
{

namespace
{

// Cells narrower than this get hairlines (DebugRenderer::hairline) for grid lines. 2-unit lines
// cover 1 - (1 - 2 / cell)^2 of the picture: about a sixth at 24 units, more than a third at 10,
// and they hide the boxes in the cells. Lab 8's grid at 10,000 balls has 16.5-unit cells. The
// software renderer draws hairlines faster too (docs/performance.md, "Seventh round").
const float hairlinesBelowCell = 24.f; // world units (pixels at 1:1)

void drawGrid(DebugRenderer& debug, const BroadphaseLayout& layout)
{
    // Too many cells drawn one by one would hide everything else: past these sizes only the
    // grid lines, then nothing.
    const std::size_t cellCount = layout.boxesPerCell.size();
    const Vec2 origin = layout.gridOrigin;
    const float cell = layout.cellSize;
    if (layout.columns <= 400 && layout.rows <= 400)
    {
        const bool hairlines = cell < hairlinesBelowCell;
        const auto gridLine = [&debug, hairlines](Vec2 from, Vec2 to)
        {
            if (hairlines)
                debug.hairline(from, to, DebugRenderer::hintColor);
            else
                debug.line(from, to, DebugRenderer::hintColor);
        };
        const float right = origin.x + cell * static_cast<float>(layout.columns);
        const float bottom = origin.y + cell * static_cast<float>(layout.rows);
        for (int column = 0; column <= layout.columns; ++column)
        {
            const float x = origin.x + cell * static_cast<float>(column);
            gridLine({x, origin.y}, {x, bottom});
        }
        for (int row = 0; row <= layout.rows; ++row)
        {
            const float y = origin.y + cell * static_cast<float>(row);
            gridLine({origin.x, y}, {right, y});
        }
    }
    if (cellCount > 20000)
        return;
    const std::size_t columns = static_cast<std::size_t>(layout.columns);
    for (std::size_t c = 0; c < cellCount; ++c)
    {
        if (layout.boxesPerCell[c] < 2)
            continue; // cells with two or more boxes are where the tests happen
        const float x = origin.x + cell * static_cast<float>(c % columns);
        const float y = origin.y + cell * static_cast<float>(c / columns);
        debug.box({x, y, cell, cell}, DebugRenderer::overlappingColor);
    }
}

} // namespace

void drawBroadphase(DebugRenderer& debug, const BroadphaseLayout& layout)
{
    if (!layout.boxesPerCell.empty())
        drawGrid(debug, layout);
    for (const Box& node : layout.nodes)
        debug.box(node, DebugRenderer::hintColor);
    // One thin bar per box, stacked in sweep order, so students see the sorted intervals.
    const float rowHeight = 3.f;
    const std::size_t shown = std::min<std::size_t>(layout.sweepIntervals.size(), 200);
    for (std::size_t i = 0; i < shown; ++i)
    {
        const Vec2 interval = layout.sweepIntervals[i];
        const float y = 4.f + rowHeight * static_cast<float>(i % 40);
        debug.line({interval.x, y}, {interval.y, y}, DebugRenderer::hintColor);
    }
}

} // namespace hitbox
