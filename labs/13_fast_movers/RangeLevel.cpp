#include "RangeLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace
{
const float laneY[RangeLevel::laneCount] = {170.f, 340.f, 510.f};
const char* const laneNames[RangeLevel::laneCount] = {"discrete", "sub-steps", "speculative"};
const std::string subStepLimit = std::to_string(std::lround(RangeLevel::maxSubStep)) + " px";
// Drawn above each lane: what moves the bullet there.
const std::string laneLabels[RangeLevel::laneCount] = {
    "discrete: one move, then one overlap test (given)",
    "sub-steps: moves of at most " + subStepLimit + ", a test after each (task 1)",
    "speculative: measure the gap ahead, move no further (task 2)"};
const sf::Color labelColor{190, 190, 200};
// The F1 view draws at most this many sub-step ticks a lane (a fast shot has thousands).
constexpr int mostTicksDrawn = 400;
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
        WallTests tests(wall);
        if (lane == 0)
            result = discreteStep(bullets[lane], speed, dt, tests);
        else if (lane == 1)
            result = subSteppedStep(bullets[lane], speed, dt, tests, maxSubStep);
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
        speed = nextShotSpeed(speed);
        fire();
    }
}

float RangeLevel::nextShotSpeed(float speed)
{
    return std::min(speed * speedUp, topSpeed);
}

float RangeLevel::getSpeed() const
{
    return speed;
}

void RangeLevel::render(sf::RenderTarget& target) const
{
    drawBox(target, wall, wallColor);
    for (int lane = 0; lane < laneCount; ++lane)
    {
        sf::Text label = hitbox::makeText(font.get(), laneLabels[lane], 16);
        label.setFillColor(labelColor);
        label.setPosition({16.f, laneY[lane] - 34.f});
        target.draw(label);
        drawBox(target, {0.f, laneY[lane] - 0.5f, getWorldSize().x, 1.f}, sf::Color(60, 64, 80));
        const Box& bullet = bullets[lane];
        // Drawn at least 8 pixels wide, so a bullet against the wall shows.
        drawBox(target, {bullet.left, bullet.top - 4.f, bullet.width, bullet.height + 8.f},
                bulletColor);
    }
}

void RangeLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    const float worldWidth = getWorldSize().x;
    const float move = speed * hitbox::stepSeconds; // this speed's move in one step
    for (int lane = 0; lane < laneCount; ++lane)
    {
        const Box& bullet = bullets[lane];
        const float front = hitbox::rightOf(bullet);
        const float middle = bullet.top + bullet.height / 2.f;
        // The bullet's state against the wall: touching it is not a hit (the edge rule).
        const hitbox::DebugState state = hitbox::boxVsBox(bullet, wall)
                                             ? hitbox::DebugState::Overlapping
                                         : front == wall.left ? hitbox::DebugState::Touching
                                                              : hitbox::DebugState::Free;
        debug.box(bullet, state);
        if (!flying[lane])
            continue;
        // The next step's whole move (clipped to the window).
        const float moveEnd = std::min(front + move, worldWidth);
        debug.arrow({front, middle}, {moveEnd, middle}, hitbox::DebugRenderer::velocityColor);
        if (lane == 1)
        {
            // Where each sub-step of the next move ends (at most maxSubStep apart).
            int ticks = 0;
            for (float x = front + maxSubStep; x < moveEnd && ticks < mostTicksDrawn;
                 x += maxSubStep, ++ticks)
                debug.line({x, middle - 6.f}, {x, middle + 6.f}, hitbox::DebugRenderer::hintColor);
        }
        else if (lane == 2 && front <= wall.left)
            // The gap measured before moving: the move is cut to it when it would cross it.
            debug.line({front, middle + 8.f}, {wall.left, middle + 8.f},
                       hitbox::DebugRenderer::normalColor);
    }
    debug.panel(
        {"F1: pink arrow = the next step's move (" + std::to_string(std::lround(move)) + " px)",
         "middle lane: ticks = where its sub-steps end (at most " + subStepLimit + " apart)",
         "bottom lane: green line = the gap measured ahead of the bullet"});
}

std::string RangeLevel::getHelpText() const
{
    return describeState();
}

std::string RangeLevel::describeState() const
{
    char text[240];
    std::snprintf(text, sizeof text,
                  "shot %d at %.0f px/s%s; through the wall: %s %d, %s %d, %s %d", shots,
                  static_cast<double>(speed), speed >= topSpeed ? " (top speed)" : "", laneNames[0],
                  throughCount[0], laneNames[1], throughCount[1], laneNames[2], throughCount[2]);
    return text;
}

int RangeLevel::getThroughCount(int lane) const
{
    return throughCount[lane];
}
