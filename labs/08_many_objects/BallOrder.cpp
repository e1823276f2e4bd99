#include "BallOrder.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace
{

// A cap on the number of tiles, so their counts (half a megabyte at most) stay in the cache.
// In lab 8's arena it only matters for tiles under 3.2 px.
const double mostTiles = 65536.0;

// The tile's column or row: 0 to count - 1, whatever the position (NaN: 0).
std::size_t clampedIndex(float position, float start, float tileSize, std::size_t count)
{
    const float index = std::floor((position - start) / tileSize);
    if (!(index > 0.f))
        return 0;
    // Capped before the conversion: a float too big for size_t would be undefined behaviour.
    return std::min(static_cast<std::size_t>(std::min(index, 1e9f)), count - 1);
}

} // namespace

void sortBallsByTile(std::vector<Ball>& balls, hitbox::Box area, float tileSize)
{
    if (!std::isfinite(area.width) || !std::isfinite(area.height))
        return; // no tiles to count: the balls keep their order
    const double width = std::max(double(area.width), 1.0);
    const double height = std::max(double(area.height), 1.0);
    double tile = tileSize > 0.f && std::isfinite(tileSize) ? double(tileSize) : width;
    // About mostTiles tiles at most, in all or in one row or column (a long thin area).
    tile = std::max(
        {tile, std::sqrt(width * height / mostTiles), width / mostTiles, height / mostTiles});
    const std::size_t columns = static_cast<std::size_t>(std::ceil(width / tile));
    const std::size_t rows = static_cast<std::size_t>(std::ceil(height / tile));
    const float size = static_cast<float>(tile);

    std::vector<std::uint32_t> tileOf(balls.size());
    std::vector<std::size_t> start(columns * rows + 1, 0);
    for (std::size_t i = 0; i < balls.size(); ++i)
    {
        const hitbox::Vec2 p = balls[i].position;
        const std::size_t t = clampedIndex(p.y, area.top, size, rows) * columns +
                              clampedIndex(p.x, area.left, size, columns);
        tileOf[i] = static_cast<std::uint32_t>(t);
        ++start[t + 1];
    }
    for (std::size_t t = 1; t < start.size(); ++t)
        start[t] += start[t - 1];
    std::vector<Ball> sorted(balls.size());
    for (std::size_t i = 0; i < balls.size(); ++i)
        sorted[start[tileOf[i]]++] = balls[i];
    balls = std::move(sorted);
}
