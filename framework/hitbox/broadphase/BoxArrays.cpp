#include "hitbox/broadphase/BoxArrays.h"

#include <cmath>
#include <limits>

namespace hitbox
{

void BoxArrays::load(const std::vector<BroadphaseItem>& items)
{
    const std::size_t count = items.size();
    minX.resize(count);
    minY.resize(count);
    maxX.resize(count);
    maxY.resize(count);
    layer.resize(count);
    mask.resize(count);
    const float inf = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < count; ++i)
    {
        layer[i] = items[i].layer;
        mask[i] = items[i].mask;
        const sf::FloatRect& box = items[i].box;
        if (!(std::isfinite(box.left) && std::isfinite(box.top) && std::isfinite(box.width) &&
              std::isfinite(box.height)))
        {
            // An empty box: min > max, so every overlap test with it is false.
            minX[i] = minY[i] = inf;
            maxX[i] = maxY[i] = -inf;
            continue;
        }
        // The same arithmetic as boxVsBox (normalised(), then left + width), so the broadphase
        // and the exact test agree to the last bit, even at huge coordinates. Written out
        // rather than calling normalised() and rightOf(): this runs for every box every frame,
        // and calls into another file are not inlined.
        const float left = box.width < 0.f ? box.left + box.width : box.left;
        const float top = box.height < 0.f ? box.top + box.height : box.top;
        minX[i] = left;
        minY[i] = top;
        maxX[i] = left + (box.width < 0.f ? sizeReaching(left, box.left) : box.width);
        maxY[i] = top + (box.height < 0.f ? sizeReaching(top, box.top) : box.height);
    }
}

} // namespace hitbox
