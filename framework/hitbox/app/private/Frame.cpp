#include "hitbox/app/private/Frame.h"

#include "hitbox/app/private/HelpLine.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/Text.hpp>
#include <SFML/System/String.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace hitbox
{
namespace
{

// Text the framework writes is UTF-8 (explain's "only touch — touching is not a collision");
// sf::String from a std::string would read it in the locale's code page and draw each byte.
sf::String utf8(const std::string& text)
{
    return sf::String::fromUtf8(text.begin(), text.end());
}

// The debug panel (DebugRenderer::panel): text lines on a dark box in the top-left corner.
void drawPanel(sf::RenderTarget& target, const sf::Font& font,
               const std::vector<std::string>& lines)
{
    if (lines.empty())
        return;
    const float lineHeight = 18.f;
    const float margin = 8.f;
    std::vector<sf::Text> texts;
    float width = 0.f;
    for (std::size_t i = 0; i < lines.size(); ++i)
    {
        texts.push_back(makeText(font, utf8(lines[i]), 14));
        texts.back().setFillColor(sf::Color(235, 235, 235));
        texts.back().setPosition({2.f * margin, 2.f * margin + lineHeight * static_cast<float>(i)});
        width = std::max(width, rectSize(texts.back().getLocalBounds()).x);
    }
    sf::RectangleShape box(
        {width + 2.f * margin, lineHeight * static_cast<float>(lines.size()) + margin});
    box.setPosition({margin, margin});
    box.setFillColor(sf::Color(0, 0, 0, 200));
    target.draw(box);
    for (const sf::Text& text : texts)
        target.draw(text);
}

void drawHelpBar(sf::RenderTarget& target, const Level& level, const sf::Font& font,
                 const FrameSettings& settings)
{
    const sf::Vector2f world = level.getWorldSize();
    const float barHeight = 24.f;
    sf::RectangleShape bar({world.x, barHeight});
    bar.setPosition({0.f, world.y - barHeight});
    bar.setFillColor(sf::Color(0, 0, 0, 170));
    target.draw(bar);
    sf::Text help =
        makeText(font, utf8(helpLine(level, settings.showDebug, settings.framesPerSecond)), 14);
    help.setFillColor(sf::Color(220, 220, 220));
    help.setPosition({8.f, world.y - barHeight + 3.f});
    target.draw(help);
}

void drawPausedTitle(sf::RenderTarget& target, sf::Vector2f world, const sf::Font& font,
                     const FrameSettings& settings)
{
    std::string title = "PAUSED  -  P to resume, N for one step";
    if (canRewind(settings.rewind, settings.paused))
        title = "PAUSED at step " + std::to_string(settings.rewind.rewind->shownStep()) +
                "  -  Left/Right or click the strip: step back/forward, P resume";
    sf::Text paused = makeText(font, title, 22);
    paused.setFillColor(sf::Color::White);
    paused.setOutlineColor(sf::Color::Black);
    paused.setOutlineThickness(2.f);
    const float width = rectSize(paused.getLocalBounds()).x;
    paused.setPosition({(world.x - width) / 2.f, 12.f});
    target.draw(paused);
}

} // namespace

void drawFrame(sf::RenderTarget& target, const Level& level, const sf::Font& font,
               const FrameSettings& settings, float leftover)
{
    const sf::Vector2f world = level.getWorldSize();
    target.clear(DebugRenderer::backgroundColor);
    level.renderBlended(target, leftover);
    if (settings.showDebug)
    {
        DebugRenderer debug;
        // The window may be shrunk to fit the screen: hairlines stay one screen pixel wide.
        debug.setScreenPixel(target.mapPixelToCoords({1, 0}).x - target.mapPixelToCoords({0, 0}).x);
        level.renderDebug(debug);
        debug.draw(target);
        drawPanel(target, font, debug.getPanel());
    }
    drawHelpBar(target, level, font, settings);
    if (canRewind(settings.rewind, settings.paused))
        drawRewindStrip(target, world, settings.rewind);
    if (settings.paused)
        drawPausedTitle(target, world, font, settings);
}

} // namespace hitbox
