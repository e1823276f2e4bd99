#include "StackLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <memory>

namespace
{
const float stackLeft[2] = {330.f, 820.f};
const sf::Color crateColor{190, 140, 80};
const sf::Color crateEdgeColor{120, 80, 40};
const sf::Color floorColor{90, 96, 110};

// True when `crate` sits exactly on the floor or on a crate below it (edges meet, no depth).
bool restsExactly(const std::vector<Crate>& crates, std::size_t index, float floorY)
{
    const Crate& crate = crates[index];
    if (crate.top + crate.size == floorY)
        return true;
    for (std::size_t other = 0; other < crates.size(); ++other)
    {
        const Crate& below = crates[other];
        const bool levelInX =
            crate.left < below.left + below.size && below.left < crate.left + crate.size;
        if (other != index && levelInX &&
            (crate.top + crate.size == below.top || below.top + below.size == crate.top))
            return true;
    }
    return false;
}
} // namespace

std::vector<hitbox::DebugState> crateStates(const std::vector<Crate>& crates, float floorY)
{
    std::vector<hitbox::DebugState> states(crates.size(), hitbox::DebugState::Free);
    const auto mark = [&states](int index, hitbox::DebugState state)
    {
        if (index == floorIndex)
            return;
        hitbox::DebugState& now = states[static_cast<std::size_t>(index)];
        if (static_cast<int>(state) > static_cast<int>(now))
            now = state; // the worst state wins: overlapping over touching over free
    };
    for (std::size_t index = 0; index < crates.size(); ++index)
        if (restsExactly(crates, index, floorY))
            states[index] = hitbox::DebugState::Touching;
    for (const Contact& contact : findContacts(crates, floorY))
    {
        const hitbox::DebugState state = contact.depth > StackLevel::restingSlop
                                             ? hitbox::DebugState::Overlapping
                                             : hitbox::DebugState::Touching;
        mark(contact.above, state);
        mark(contact.below, state);
    }
    return states;
}

StackLevel::StackLevel()
{
    restack();
}

void StackLevel::restack()
{
    for (int stack = 0; stack < 2; ++stack)
    {
        stacks[stack].clear();
        for (int index = 0; index < crateCount; ++index)
        {
            // Each crate exactly on the one below, a few pixels to the side so it looks piled.
            const float sideways = static_cast<float>((index * 7) % 5) - 2.f;
            stacks[stack].push_back({stackLeft[stack] + sideways,
                                     floorY - crateSize * static_cast<float>(index + 1), crateSize,
                                     0.f});
        }
        largestMoveNow[stack] = 0.f;
        largestMoveShown[stack] = 0.f;
    }
    stepsInWindow = 0;
}

void StackLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.isPressed(sf::Keyboard::Key::Up))
        passes[1] = std::min(passes[1] + 1, maxPasses);
    if (input.isPressed(sf::Keyboard::Key::Down))
        passes[1] = std::max(passes[1] - 1, 1);
    if (input.isPressed(sf::Keyboard::Key::R))
        restack();
}

void StackLevel::update(float dt)
{
    for (int stack = 0; stack < 2; ++stack)
    {
        const std::vector<Crate> before = stacks[stack];
        fall(stacks[stack], dt);
        resolvePenetrations(stacks[stack], floorY, passes[stack]);
        largestMoveNow[stack] = std::max(largestMoveNow[stack], largestMove(before, stacks[stack]));
    }
    if (++stepsInWindow == stepsPerReadout)
    {
        for (int stack = 0; stack < 2; ++stack)
        {
            largestMoveShown[stack] = largestMoveNow[stack];
            largestMoveNow[stack] = 0.f;
        }
        stepsInWindow = 0;
    }
}

void StackLevel::render(sf::RenderTarget& target) const
{
    sf::RectangleShape floor({getWorldSize().x, getWorldSize().y - floorY});
    floor.setPosition({0.f, floorY});
    floor.setFillColor(floorColor);
    target.draw(floor);
    for (const std::vector<Crate>& stack : stacks)
    {
        for (const Crate& crate : stack)
        {
            sf::RectangleShape picture({crate.size - 2.f, crate.size - 2.f});
            picture.setPosition({crate.left + 1.f, crate.top + 1.f});
            picture.setFillColor(crateColor);
            picture.setOutlineColor(crateEdgeColor);
            picture.setOutlineThickness(1.f);
            target.draw(picture);
        }
    }
}

void StackLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    for (const std::vector<Crate>& stack : stacks)
    {
        const std::vector<hitbox::DebugState> states = crateStates(stack, floorY);
        for (std::size_t index = 0; index < stack.size(); ++index)
        {
            const Crate& crate = stack[index];
            debug.box({crate.left, crate.top, crate.size, crate.size}, states[index]);
            // The velocity, a tenth of a second ahead.
            const hitbox::Vec2 center{crate.left + crate.size / 2.f, crate.top + crate.size / 2.f};
            debug.arrow(center, {center.x, center.y + crate.velocityY * 0.1f},
                        hitbox::DebugRenderer::velocityColor);
        }
    }
    debug.line({0.f, floorY}, {getWorldSize().x, floorY}, hitbox::DebugRenderer::hintColor);
    char slop[120];
    std::snprintf(slop, sizeof slop, "resting: up to %.0f px deep counts as touching (the slop)",
                  static_cast<double>(restingSlop));
    debug.panel({slop});
}

std::string StackLevel::getHelpText() const
{
    char text[120];
    std::snprintf(text, sizeof text,
                  "Up/Down passes   R restack  |  a step moves %.2f px (%d), %.2f px (%d)",
                  static_cast<double>(largestMoveShown[0]), passes[0],
                  static_cast<double>(largestMoveShown[1]), passes[1]);
    return text;
}

std::string StackLevel::describeState() const
{
    char text[200];
    std::snprintf(text, sizeof text,
                  "left: %d pass, moves %.2f px a step, overlap %.1f px; right: %d passes, "
                  "moves %.2f px a step, overlap %.1f px",
                  passes[0], static_cast<double>(largestMoveShown[0]),
                  static_cast<double>(deepestOverlap(stacks[0], floorY)), passes[1],
                  static_cast<double>(largestMoveShown[1]),
                  static_cast<double>(deepestOverlap(stacks[1], floorY)));
    return text;
}

float StackLevel::getShake(int stack) const
{
    return largestMoveShown[stack];
}

const std::vector<Crate>& StackLevel::getCrates(int stack) const
{
    return stacks[stack];
}

int StackLevel::getPasses(int stack) const
{
    return passes[stack];
}

using StackSnapshot = hitbox::WholeLevelCopy<StackLevel>; // Level.h: a copy of the whole level

std::unique_ptr<hitbox::LevelState> StackLevel::saveState() const
{
    const std::size_t held =
        sizeof(StackSnapshot) + (stacks[0].size() + stacks[1].size()) * sizeof(Crate);
    return std::make_unique<StackSnapshot>(*this, held);
}

void StackLevel::restoreState(const hitbox::LevelState& state)
{
    *this = static_cast<const StackSnapshot&>(state).level;
}
