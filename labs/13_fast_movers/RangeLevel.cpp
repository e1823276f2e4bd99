#include "RangeLevel.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <cstdio>

namespace
{
const float laneY[RangeLevel::laneCount] = {170.f, 340.f, 510.f};
const char* const laneNames[RangeLevel::laneCount] = {"discrete", "sub-steps", "speculative"};
const sf::Color bulletColor{240, 200, 80};
const sf::Color wallColor{200, 200, 210};

void drawBox(sf::RenderTarget& target, const Box& box, sf::Color color)
{
    sf::RectangleShape picture({box.width, box.height});
    picture.setPosition({box.left, box.top});
    picture.setFillColor(color);
    target.draw(picture);
}
} // namespace

RangeLevel::RangeLevel() : wall{900.f, 60.f, 6.f, 560.f}
{
    fire();
}

void RangeLevel::fire()
{
    for (int lane = 0; lane < laneCount; ++lane)
    {
        bullets[lane] = {100.f, laneY[lane] - 2.f, 8.f, 4.f};
        flying[lane] = true;
    }
    ++shots;
}

void RangeLevel::update(float dt)
{
    for (int lane = 0; lane < laneCount; ++lane)
    {
        if (!flying[lane])
            continue;
        MoveResult result;
        if (lane == 0)
            result = discreteStep(bullets[lane], speed, dt, wall);
        else if (lane == 1)
            result = subSteppedStep(bullets[lane], speed, dt, wall, maxSubStep);
        else
            result = speculativeStep(bullets[lane], speed, dt, wall);
        bullets[lane] = result.bullet;
        if (result.hitWall)
            flying[lane] = false;
        else if (bullets[lane].left >= getWorldSize().x)
        {
            flying[lane] = false;
            ++throughCount[lane];
        }
    }
    if (!flying[0] && !flying[1] && !flying[2])
    {
        speed = speed * speedUp > 1e6f ? firstSpeed : speed * speedUp;
        fire();
    }
}

void RangeLevel::render(sf::RenderTarget& target) const
{
    drawBox(target, wall, wallColor);
    for (int lane = 0; lane < laneCount; ++lane)
    {
        drawBox(target, {0.f, laneY[lane] - 0.5f, getWorldSize().x, 1.f}, sf::Color(60, 64, 80));
        const Box& bullet = bullets[lane];
        // Drawn at least 8 pixels wide, so a bullet against the wall shows.
        drawBox(target, {bullet.left, bullet.top - 4.f, bullet.width, bullet.height + 8.f},
                bulletColor);
    }
}

std::string RangeLevel::getHelpText() const
{
    return describeState();
}

std::string RangeLevel::describeState() const
{
    char text[200];
    std::snprintf(text, sizeof text, "shot %d at %.0f px/s; through the wall: %s %d, %s %d, %s %d",
                  shots, static_cast<double>(speed), laneNames[0], throughCount[0], laneNames[1],
                  throughCount[1], laneNames[2], throughCount[2]);
    return text;
}

int RangeLevel::getThroughCount(int lane) const
{
    return throughCount[lane];
}
