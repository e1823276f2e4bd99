#include "BallsLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/objects/Collision.h"
// Your own class from lab 0: README.md, "Using your own Collision class from lab 0".
#include "MyCollision.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>

namespace
{
const sf::Color ballColors[] = {{230, 90, 70},   {70, 150, 230}, {240, 200, 60}, {90, 200, 120},
                                {200, 110, 220}, {240, 150, 70}, {80, 210, 210}, {220, 220, 220}};
} // namespace

BallsLevel::BallsLevel(int ballCount, unsigned seed) : random(seed)
{
    startWithTwoBalls();
    while (getBallCount() < std::min(ballCount, maxBalls))
        addRandomBall();
}

void BallsLevel::startWithTwoBalls()
{
    removeAllBalls();
    const sf::Vector2f world = getWorldSize();
    addBall({world.x * 0.25f, world.y / 2.f}, {ballSpeed, 0.f});
    addBall({world.x * 0.75f, world.y / 2.f}, {-ballSpeed, 0.f});
}

void BallsLevel::addRandomBall()
{
    const sf::Vector2f world = getWorldSize();
    std::uniform_real_distribution<float> x(ballRadius, world.x - ballRadius);
    std::uniform_real_distribution<float> y(ballRadius, world.y - ballRadius);
    std::uniform_real_distribution<float> angle(0.f, 2.f * hitbox::pi);
    // Try a few places; a ball that starts inside another would be shot out of it.
    for (int attempt = 0; attempt < 100; ++attempt)
    {
        const sf::Vector2f center{x(random), y(random)};
        bool free = true;
        for (const Ball& ball : balls)
        {
            const sf::Vector2f between = ball.getPosition() - center;
            free = free &&
                   between.x * between.x + between.y * between.y > 4.f * ballRadius * ballRadius;
        }
        if (free)
        {
            const float direction = angle(random);
            addBall(center, {ballSpeed * std::cos(direction), ballSpeed * std::sin(direction)});
            return;
        }
    }
}

void BallsLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.isPressed(sf::Keyboard::Key::Space) && getBallCount() < maxBalls)
        addRandomBall();
    if (input.isPressed(sf::Keyboard::Key::R))
        startWithTwoBalls();
}

void BallsLevel::update(float dt)
{
    for (Ball& ball : balls)
        ball.update(dt);

    // Every pair once: ball i against every ball after it. n balls make n(n-1)/2 pairs.
    for (std::size_t i = 0; i < balls.size(); ++i)
    {
        for (std::size_t j = i + 1; j < balls.size(); ++j)
        {
            // BEGIN TASK 2: test each pair with the bounding circle
            // Circles overlap when the distance between the centres is less than the sum
            // of the radii; Collision::checkBoundingCircle compares the squares of the two,
            // which needs no square root.
            if (hitbox::Collision::checkBoundingCircle(&balls[i], &balls[j]))
            {
                balls[i].collisionResponse(&balls[j]);
                balls[j].collisionResponse(&balls[i]);
            }
            // END TASK 2
            // Task 3's response, for every pair: it leaves balls that do not overlap alone. Called
            // here, not in task 2, so each task's tests see that task's code alone.
            bounceApart(balls[i], balls[j]);
        }
    }
}

void BallsLevel::render(sf::RenderTarget& target) const
{
    for (const Ball& ball : balls)
    {
        sf::CircleShape drawn(ball.getRadius(), 48);
        drawn.setOrigin({ball.getRadius(), ball.getRadius()});
        drawn.setPosition(ball.getPosition());
        // Mix towards white just after a hit, so every hit is seen.
        const sf::Color color = ball.getFillColor();
        const float white = ball.getFlash() * 0.7f;
        const auto mix = [white](std::uint8_t channel)
        { return static_cast<std::uint8_t>(channel + (255 - channel) * white); };
        drawn.setFillColor(sf::Color(mix(color.r), mix(color.g), mix(color.b)));
        target.draw(drawn);
    }
}

void BallsLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    for (const Ball& ball : balls)
        debug.objectCircle(ball, ball.getFlash() > 0.f);
}

std::string BallsLevel::getHelpText() const
{
    return "Space add a ball   R two balls again";
}

std::string BallsLevel::describeState() const
{
    int hits = 0;
    for (const Ball& ball : balls)
        hits += ball.getHitCount();
    char text[120];
    std::snprintf(text, sizeof text, "%d balls, %d hits so far", getBallCount(), hits);
    return text;
}

void BallsLevel::removeAllBalls()
{
    balls.clear();
}

void BallsLevel::addBall(sf::Vector2f center, sf::Vector2f velocity)
{
    const int index = getBallCount();
    balls.emplace_back(center, velocity, ballColors[index % std::size(ballColors)]);
    balls.back().setWorldSize(getWorldSize());
}

int BallsLevel::getBallCount() const
{
    return static_cast<int>(balls.size());
}

const Ball& BallsLevel::getBall(int index) const
{
    return balls.at(static_cast<std::size_t>(index));
}
