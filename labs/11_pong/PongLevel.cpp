#include "PongLevel.h"

#include "Court.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <cmath>
#include <cstdio>

namespace
{
const sf::Color lineColor{90, 96, 112};
const sf::Color scoreColor{150, 156, 172};

// -1 while `up` is held, +1 while `down` is, 0 for neither or both.
float keyDirection(const hitbox::Input& input, sf::Keyboard::Key up, sf::Keyboard::Key down)
{
    return (input.isKeyDown(down) ? 1.f : 0.f) - (input.isKeyDown(up) ? 1.f : 0.f);
}

void drawStrip(sf::RenderTarget& target, sf::Vector2f topLeft, sf::Vector2f size)
{
    sf::RectangleShape strip(size);
    strip.setPosition(topLeft);
    strip.setFillColor(lineColor);
    target.draw(strip);
}
} // namespace

PongLevel::PongLevel(unsigned seed, int players)
    : computerPlaysLeft(players == 0), computerPlaysRight(players < 2), random(seed)
{
    serveTowards(std::bernoulli_distribution(0.5)(random) ? 1 : -1);
}

void PongLevel::handleInput(const hitbox::Input& input, float)
{
    leftDirection = keyDirection(input, sf::Keyboard::Key::W, sf::Keyboard::Key::S);
    rightDirection = keyDirection(input, sf::Keyboard::Key::Up, sf::Keyboard::Key::Down);
    if (input.isPressed(sf::Keyboard::Key::C))
        computerPlaysRight = !computerPlaysRight;
}

void PongLevel::update(float dt)
{
    // 1. Where each paddle goes this step (task 1), steered by keys or the computer (6).
    const float leftWish = computerPlaysLeft ? computerDirection(ball, left, dt) : leftDirection;
    const float rightWish =
        computerPlaysRight ? computerDirection(ball, right, dt) : rightDirection;
    left.setPlannedMove(left.moveWithinCourt(leftWish, dt));
    right.setPlannedMove(right.moveWithinCourt(rightWish, dt));
    // 2. The ball swept against the moving paddles (task 5), which return it (task 3).
    moveBall(ball, left, right, dt);
    left.finishMove();
    right.finishMove();
    // 3. The walls (task 2), and 4. a point and the next serve (task 4).
    ball.bounceOffWalls();
    scoreAndServe();
}

void PongLevel::scoreAndServe()
{
    // BEGIN TASK 4: score and serve
    // Out means no area shared with the court, so a ball touching the line from outside is
    // out. The player who lost the point receives the serve.
    const hitbox::Box box = hitbox::toBox(ball.getCollisionBox());
    if (hitbox::rightOf(box) <= court.left)
    {
        ++rightScore;
        serveTowards(-1);
    }
    else if (box.left >= court.right)
    {
        ++leftScore;
        serveTowards(1);
    }
    // END TASK 4
}

void PongLevel::serveTowards(int direction)
{
    std::uniform_real_distribution<float> degrees(-maxServeDegrees, maxServeDegrees);
    const float angle = degrees(random) * hitbox::pi / 180.f;
    const float towards = direction < 0 ? -1.f : 1.f;
    ball.placeAt({(court.left + court.right) / 2.f, (court.top + court.bottom) / 2.f},
                 {towards * ballSpeed * std::cos(angle), ballSpeed * std::sin(angle)});
}

void PongLevel::render(sf::RenderTarget& target) const
{
    const float middleX = (court.left + court.right) / 2.f;
    drawStrip(target, {court.left, court.top - 8.f}, {court.right - court.left, 8.f});
    drawStrip(target, {court.left, court.bottom}, {court.right - court.left, 8.f});
    for (float y = court.top + 8.f; y < court.bottom; y += 32.f)
        drawStrip(target, {middleX - 2.f, y}, {4.f, 16.f});

    char number[16];
    std::snprintf(number, sizeof number, "%d", leftScore);
    sf::Text score = hitbox::makeText(font.get(), number, 64);
    score.setFillColor(scoreColor);
    score.setPosition({middleX - 120.f, court.top + 16.f});
    target.draw(score);
    std::snprintf(number, sizeof number, "%d", rightScore);
    score.setString(number);
    score.setPosition({middleX + 80.f, court.top + 16.f});
    target.draw(score);

    target.draw(left);
    target.draw(right);
    target.draw(ball);
}

void PongLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    debug.box({court.left, court.top, court.right - court.left, court.bottom - court.top},
              sf::Color(120, 220, 120));
    debug.objectBox(left, false);
    debug.objectBox(right, false);
    debug.objectBox(ball, false);
}

std::string PongLevel::getHelpText() const
{
    const std::string leftKeys = computerPlaysLeft ? "" : "W/S left paddle   ";
    return leftKeys + (computerPlaysRight ? "C two players" : "Up/Down right paddle   C computer");
}

std::string PongLevel::describeState() const
{
    char text[120];
    std::snprintf(text, sizeof text, "score %d : %d, ball at (%.0f, %.0f)", leftScore, rightScore,
                  static_cast<double>(ball.getPosition().x),
                  static_cast<double>(ball.getPosition().y));
    return text;
}

Ball& PongLevel::getBall()
{
    return ball;
}

Paddle& PongLevel::getLeftPaddle()
{
    return left;
}

Paddle& PongLevel::getRightPaddle()
{
    return right;
}

int PongLevel::getLeftScore() const
{
    return leftScore;
}

int PongLevel::getRightScore() const
{
    return rightScore;
}

void PongLevel::setComputerPlaysRight(bool playing)
{
    computerPlaysRight = playing;
}
