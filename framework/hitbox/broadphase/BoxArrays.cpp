#include "hitbox/broadphase/BoxArrays.h"

#include "hitbox/geometry/Shapes.h"

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
        const Box& box = items[i].box;
        if (!(std::isfinite(box.left) && std::isfinite(box.top) && std::isfinite(box.width) &&
              std::isfinite(box.height)))
        {
            // An empty box: min > max, so every overlap test with it is false.
            minX[i] = minY[i] = inf;
            maxX[i] = maxY[i] = -inf;
            continue;
        }
        // The same arithmetic as boxVsBox (normalised(), then left + width), so the broadphase
        // and the exact test agree to the last bit, even at huge coordinates.
        const Box upright = normalised(box);
        minX[i] = upright.left;
        minY[i] = upright.top;
        maxX[i] = upright.left + upright.width;
        maxY[i] = upright.top + upright.height;
    }
}

} // namespace hitbox
