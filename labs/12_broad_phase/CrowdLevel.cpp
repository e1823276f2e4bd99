#include "CrowdLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>

namespace
{
const sf::Color freeColor{70, 110, 190};
const sf::Color overlapColor{210, 70, 60};
const char* const methodNames[] = {"brute force", "sort and sweep", "grid"};
} // namespace

CrowdLevel::CrowdLevel(int boxCount, unsigned seed)
{
    std::mt19937 random(seed);
    const sf::Vector2f world = getWorldSize();
    std::uniform_real_distribution<float> size(10.f, 40.f);
    std::uniform_real_distribution<float> speed(-60.f, 60.f);
    for (int index = 0; index < boxCount; ++index)
    {
        const float width = size(random);
        const float height = size(random);
        const float left = std::uniform_real_distribution<float>(0.f, world.x - width)(random);
        const float top = std::uniform_real_distribution<float>(0.f, world.y - height)(random);
        boxes.push_back({left, top, width, height});
        speedX.push_back(speed(random));
        speedY.push_back(speed(random));
    }
    update(0.f);
}

void CrowdLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.isPressed(sf::Keyboard::Key::M))
        method = static_cast<Method>((static_cast<int>(method) + 1) % 3);
}

void CrowdLevel::update(float dt)
{
    const sf::Vector2f world = getWorldSize();
    sweepLineX = std::fmod(sweepLineX + sweepLineSpeed * dt, world.x);
    for (std::size_t index = 0; index < boxes.size(); ++index)
    {
        Box& box = boxes[index];
        const float dx = speedX[index] * dt;
        const float dy = speedY[index] * dt;
        box = {box.left + dx, box.top + dy, box.width, box.height};
        if ((box.left < 0.f && speedX[index] < 0.f) ||
            (hitbox::rightOf(box) > world.x && speedX[index] > 0.f))
            speedX[index] = -speedX[index];
        if ((box.top < 0.f && speedY[index] < 0.f) ||
            (hitbox::bottomOf(box) > world.y && speedY[index] > 0.f))
            speedY[index] = -speedY[index];
    }
    ExactBoxTests exact(boxes, ExactBoxTests::Keep::CountOnly);
    switch (method)
    {
    case Method::BruteForce:
        lastPairs = bruteForcePairs(boxes, exact);
        break;
    case Method::SortAndSweep:
        lastPairs = sortAndSweepPairs(boxes, exact);
        break;
    case Method::Grid:
        lastPairs = gridPairs(boxes, cellSize, exact);
        break;
    }
    lastExactTests = exact.count();
    overlapping.assign(boxes.size(), false);
    for (const Pair& pair : lastPairs)
        overlapping[pair.first] = overlapping[pair.second] = true;
}

void CrowdLevel::render(sf::RenderTarget& target) const
{
    for (std::size_t index = 0; index < boxes.size(); ++index)
    {
        const Box& box = boxes[index];
        sf::RectangleShape picture({box.width, box.height});
        picture.setPosition({box.left, box.top});
        picture.setFillColor(overlapping[index] ? overlapColor : freeColor);
        picture.setOutlineThickness(-1.f);
        picture.setOutlineColor(sf::Color(20, 24, 32));
        target.draw(picture);
    }
}

void CrowdLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    const sf::Vector2f world = getWorldSize();
    if (method == Method::Grid)
    {
        for (float x = 0.f; x <= world.x; x += cellSize)
            debug.line({x, 0.f}, {x, world.y}, hitbox::DebugRenderer::hintColor);
        for (float y = 0.f; y <= world.y; y += cellSize)
            debug.line({0.f, y}, {world.x, y}, hitbox::DebugRenderer::hintColor);
    }
    // The sweep line and the boxes open where it is in pink (velocityColor, reddish purple);
    // other boxes vermillion (overlapping) or sky blue (free).
    const bool sweeping = method == Method::SortAndSweep;
    if (sweeping)
        debug.line({sweepLineX, 0.f}, {sweepLineX, world.y}, hitbox::DebugRenderer::velocityColor);
    for (std::size_t index = 0; index < boxes.size(); ++index)
    {
        const Box& box = boxes[index];
        sf::Color color = overlapping[index] ? hitbox::DebugRenderer::overlappingColor
                                             : hitbox::DebugRenderer::freeColor;
        if (sweeping && box.left <= sweepLineX && sweepLineX < hitbox::rightOf(box))
            color = hitbox::DebugRenderer::velocityColor;
        debug.box(box, color);
    }
}

std::string CrowdLevel::getHelpText() const
{
    return "M method   " + describeState();
}

std::string CrowdLevel::describeState() const
{
    const long long count = static_cast<long long>(boxes.size());
    char text[160];
    std::snprintf(text, sizeof text, "%s: %lld exact tests of %lld pairs, %zu overlapping",
                  methodNames[static_cast<int>(method)], lastExactTests, count * (count - 1) / 2,
                  lastPairs.size());
    return text;
}

const std::vector<Pair>& CrowdLevel::getLastPairs() const
{
    return lastPairs;
}

long long CrowdLevel::getLastExactTests() const
{
    return lastExactTests;
}

using CrowdSnapshot = hitbox::WholeLevelCopy<CrowdLevel>; // Level.h: a copy of the whole level

std::unique_ptr<hitbox::LevelState> CrowdLevel::saveState() const
{
    const std::size_t held = sizeof(CrowdSnapshot) + boxes.size() * sizeof(Box) +
                             (speedX.size() + speedY.size()) * sizeof(float) +
                             lastPairs.size() * sizeof(Pair) + overlapping.size() / 8;
    return std::make_unique<CrowdSnapshot>(*this, held);
}

void CrowdLevel::restoreState(const hitbox::LevelState& state)
{
    *this = static_cast<const CrowdSnapshot&>(state).level;
}
