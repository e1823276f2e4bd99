#include "MovingBoxes.h"

#include <cmath>
#include <random>

namespace
{
constexpr float kSmallestSide = 0.5f;
constexpr float kLargestSide = 2.0f;
constexpr float kTopSpeed = 2.f;         // units per second
constexpr float kFrameTime = 1.f / 60.f; // seconds
// Two boxes of average sides overlap when their centres are within (wa+wb) x (ha+hb) = 2.5 x
// 2.5 units of each other, so with this much area per box each overlaps about three others.
constexpr float kAreaPerBox = 2.5f * 2.5f / 3.f;
} // namespace

MovingBoxes::MovingBoxes(std::size_t count, unsigned seed)
{
    std::mt19937 random(seed);
    worldSide = std::sqrt(kAreaPerBox * static_cast<float>(count));
    std::uniform_real_distribution<float> position(0.f, worldSide - kLargestSide);
    std::uniform_real_distribution<float> side(kSmallestSide, kLargestSide);
    std::uniform_real_distribution<float> speed(-kTopSpeed, kTopSpeed);
    for (std::size_t i = 0; i < count; ++i)
    {
        width.push_back(side(random));
        height.push_back(side(random));
        x.push_back(position(random));
        y.push_back(position(random));
        velocityX.push_back(speed(random));
        velocityY.push_back(speed(random));
    }
    lastMove.resize(count);
    items.resize(count);
    for (std::size_t i = 0; i < count; ++i)
        items[i].box = {x[i], y[i], width[i], height[i]};
}

void MovingBoxes::step()
{
    const std::size_t count = x.size();
    for (std::size_t i = 0; i < count; ++i)
    {
        float newX = x[i] + velocityX[i] * kFrameTime;
        float newY = y[i] + velocityY[i] * kFrameTime;
        if (newX < 0.f || newX + width[i] > worldSide)
        {
            velocityX[i] = -velocityX[i];
            newX = x[i];
        }
        if (newY < 0.f || newY + height[i] > worldSide)
        {
            velocityY[i] = -velocityY[i];
            newY = y[i];
        }
        lastMove[i] = {newX - x[i], newY - y[i]};
        x[i] = newX;
        y[i] = newY;
        items[i].box = {newX, newY, width[i], height[i]};
    }
}
