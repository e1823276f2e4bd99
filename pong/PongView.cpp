// PongView.cpp - how Pong looks. Only drawing: every function here reads the level's state
// and changes nothing (the rules are in PongLevel.cpp), so the game runs the same with no
// window at all.
#include "PongLevel.h"

#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/sfml/Conversions.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderStates.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <cmath>
#include <string>

namespace
{
const sf::Color wallColor(200, 204, 214);
const sf::Color netColor(90, 96, 112);
const sf::Color scoreColor(225, 228, 236);
const sf::Color dimTextColor(160, 166, 180);
const sf::Color highlightColor(255, 214, 90);

// Text centred horizontally on `centerX`, its top at `top`.
void drawCentered(sf::RenderTarget& target, const sf::Font& font, const std::string& line,
                  unsigned size, float centerX, float top, sf::Color color)
{
    sf::Text text = hitbox::makeText(font, sf::String::fromUtf8(line.begin(), line.end()), size);
    text.setFillColor(color);
    const hitbox::Box bounds = hitbox::toBox(text.getLocalBounds());
    text.setPosition(
        {std::round(centerX - bounds.left - bounds.width / 2.f), std::round(top - bounds.top)});
    target.draw(text);
}

void drawPanel(sf::RenderTarget& target, const hitbox::Box& area)
{
    sf::RectangleShape panel({area.width, area.height});
    panel.setPosition({area.left, area.top});
    panel.setFillColor(sf::Color(10, 12, 18));
    panel.setOutlineColor(netColor);
    panel.setOutlineThickness(2.f);
    target.draw(panel);
}

std::string describeMode(Mode mode, Difficulty difficulty)
{
    if (mode == Mode::OnePlayer)
        return "1 player vs computer (" + nameOf(difficulty) + ")";
    if (mode == Mode::TwoPlayers)
        return "2 players";
    return "computer vs computer (" + nameOf(difficulty) + ")";
}

std::string winnerLine(Mode mode, Side winner)
{
    if (mode == Mode::OnePlayer)
        return winner == Side::Left ? "YOU WIN!" : "THE COMPUTER WINS";
    return winner == Side::Left ? "LEFT PLAYER WINS" : "RIGHT PLAYER WINS";
}
} // namespace

namespace
{
// Draws `object` where it was `leftover` of the way from `stepStart` to where it is now
// (Nystrom, Game Programming Patterns, "Game Loop": render(lag / MS_PER_UPDATE)). A jump
// longer than any step's move (a serve from the middle) is drawn where it landed.
sf::RenderStates between(const hitbox::GameObject& object, sf::Vector2f stepStart, float leftover)
{
    const float longestMove = 60.f;
    const sf::Vector2f move = object.getPosition() - stepStart;
    sf::RenderStates states;
    if (std::abs(move.x) < longestMove && std::abs(move.y) < longestMove)
        states.transform.translate((leftover - 1.f) * move);
    return states;
}
} // namespace

void PongLevel::render(sf::RenderTarget& target) const
{
    renderBlended(target, 1.f);
}

void PongLevel::renderBlended(sf::RenderTarget& target, float leftover) const
{
    const sf::RenderStates leftAt = between(leftPaddle, leftStepStart, leftover);
    const sf::RenderStates rightAt = between(rightPaddle, rightStepStart, leftover);
    const float centerX = arena.centerX();

    // The court: walls and the dashed centre line (the "net").
    for (const hitbox::Box strip :
         {hitbox::toBox(arena.topWallStrip()), hitbox::toBox(arena.bottomWallStrip())})
    {
        sf::RectangleShape wall({strip.width, strip.height});
        wall.setPosition({strip.left, strip.top});
        wall.setFillColor(wallColor);
        target.draw(wall);
    }
    const float dash = 18.f;
    for (float y = arena.playTop() + dash / 2.f; y < arena.playBottom(); y += 2.f * dash)
    {
        sf::RectangleShape piece({4.f, std::min(dash, arena.playBottom() - y)});
        piece.setPosition({centerX - 2.f, y});
        piece.setFillColor(netColor);
        target.draw(piece);
    }

    if (screen == Screen::Title)
    {
        target.draw(leftPaddle, leftAt);
        target.draw(rightPaddle, rightAt);
        const hitbox::Box panel{centerX - 330.f, 110.f, 660.f, 420.f};
        drawPanel(target, panel);
        drawCentered(target, font.get(), "PONG", 96, centerX, 140.f, scoreColor);
        drawCentered(target, font.get(),
                     "first to " + std::to_string(settings.pointsToWin) +
                         "   -   computer: " + nameOf(settings.difficulty),
                     22, centerX, 260.f, highlightColor);
        const std::string menu[] = {
            "1   one player against the computer", "2   two players (W/S and Up/Down)",
            "3   watch computer against computer", "D   difficulty     Left/Right   points to win"};
        float y = 315.f;
        for (const std::string& line : menu)
        {
            drawCentered(target, font.get(), line, 24, centerX, y, scoreColor);
            y += 40.f;
        }
        drawCentered(target, font.get(), "left alone, the game plays itself", 16, centerX, 490.f,
                     dimTextColor);
        return;
    }

    // Scores either side of the net, big enough to read from the back of a lecture hall.
    drawCentered(target, font.get(), std::to_string(score.pointsOf(Side::Left)), 88,
                 centerX - 110.f, 36.f, scoreColor);
    drawCentered(target, font.get(), std::to_string(score.pointsOf(Side::Right)), 88,
                 centerX + 110.f, 36.f, scoreColor);
    const std::string status =
        attractMode ? "DEMO  -  press any key to play" : describeMode(mode, settings.difficulty);
    // On a dark strip, so the net does not run through the words.
    sf::RectangleShape strip({440.f, 48.f});
    strip.setPosition({centerX - 220.f, arena.playBottom() - 48.f});
    strip.setFillColor(hitbox::DebugRenderer::backgroundColor);
    target.draw(strip);
    drawCentered(target, font.get(), status, 18, centerX, arena.playBottom() - 34.f,
                 attractMode ? highlightColor : dimTextColor);
    if (muted)
        drawCentered(target, font.get(), "sound off (M)", 16, arena.size.x - 80.f, 24.f,
                     dimTextColor);

    target.draw(leftPaddle, leftAt);
    target.draw(rightPaddle, rightAt);
    if (screen == Screen::Play)
    {
        target.draw(ball, between(ball, ballStepStart, leftover));
        return;
    }

    // Win screen.
    const hitbox::Box panel{centerX - 320.f, 190.f, 640.f, 250.f};
    drawPanel(target, panel);
    drawCentered(target, font.get(), winnerLine(mode, score.getWinner()), 56, centerX, 225.f,
                 highlightColor);
    drawCentered(target, font.get(),
                 std::to_string(score.pointsOf(Side::Left)) + "  -  " +
                     std::to_string(score.pointsOf(Side::Right)),
                 40, centerX, 310.f, scoreColor);
    const std::string next = mode == Mode::ComputerVsComputer
                                 ? "the next match starts by itself   -   Esc: menu"
                                 : "Space: play again   -   Esc: menu";
    drawCentered(target, font.get(), next, 20, centerX, 385.f, dimTextColor);
}

void PongLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    const bool touching = secondsSinceContact < 0.15f;
    debug.objectBox(leftPaddle, false);
    debug.objectBox(rightPaddle, false);
    if (screen != Screen::Play)
        return;
    // The ball's box with its velocity arrow, and the line it swept along in the last step.
    debug.objectBox(ball, touching);
    debug.line(hitbox::toVec2(ballStepStart), hitbox::toVec2(ball.getPosition()),
               hitbox::DebugRenderer::hintColor);
    // Where the last contact was and which way it pushed.
    if (lastHit.hit)
        debug.contact({true, lastHit.normal, 0.f, lastHit.point});
    // Where each computer paddle is heading.
    if (isComputer(Side::Left) && leftComputer.getTargetY() >= 0.f)
        debug.cross({leftPaddle.getPosition().x, leftComputer.getTargetY()}, 8.f,
                    hitbox::DebugRenderer::hintColor);
    if (isComputer(Side::Right) && rightComputer.getTargetY() >= 0.f)
        debug.cross({rightPaddle.getPosition().x, rightComputer.getTargetY()}, 8.f,
                    hitbox::DebugRenderer::hintColor);
}
