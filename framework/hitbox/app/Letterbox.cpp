#include "hitbox/app/Letterbox.h"

#include <algorithm>
#include <cmath>

namespace hitbox
{

sf::Vector2u fitInside(sf::Vector2f size, sf::Vector2u limit)
{
    const double width = size.x >= 1.f ? static_cast<double>(size.x) : 1.0;
    const double height = size.y >= 1.f ? static_cast<double>(size.y) : 1.0;
    const double wide = std::max(1u, limit.x);
    const double tall = std::max(1u, limit.y);
    const double scale = std::min({1.0, wide / width, tall / height});
    auto side = [](double pixels, double most)
    { return static_cast<unsigned>(std::clamp(std::floor(pixels), 1.0, most)); };
    return {side(width * scale, wide), side(height * scale, tall)};
}

sf::FloatRect letterboxViewport(sf::Vector2u windowSize, sf::Vector2f worldSize)
{
    if (windowSize.x == 0 || windowSize.y == 0 || !(worldSize.x > 0.f) || !(worldSize.y > 0.f))
        return sf::FloatRect({0.f, 0.f}, {1.f, 1.f});
    const float windowAspect = static_cast<float>(windowSize.x) / static_cast<float>(windowSize.y);
    const float worldAspect = worldSize.x / worldSize.y;
    if (windowAspect > worldAspect)
    {
        // Window too wide: bars left and right.
        const float width = worldAspect / windowAspect;
        return sf::FloatRect({(1.f - width) / 2.f, 0.f}, {width, 1.f});
    }
    // Window too tall: bars above and below.
    const float height = windowAspect / worldAspect;
    return sf::FloatRect({0.f, (1.f - height) / 2.f}, {1.f, height});
}

} // namespace hitbox
