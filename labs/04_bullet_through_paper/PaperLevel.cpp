#include "PaperLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
// The numbers to play with.
const float firstSpeed = 600.f;        // pixels per second of the first automatic shot
const float speedFactor = 1.6f;        // each automatic shot is this much faster
const float maxSpeed = 1000000.f;      // then start again from firstSpeed
const float pauseBetweenShots = 0.35f; // seconds to look at where the last shot ended

const float wallThickness = 4.f; // the sheet of paper
const float wallX = 860.f;
const float gunX = 70.f;
const float discreteLaneY = 215.f;
const float sweptLaneY = 455.f;

const sf::Color paperColor{235, 235, 225};
const sf::Color laneColor{32, 36, 50};
const sf::Color hitColor{90, 220, 120};
const sf::Color missColor{255, 90, 80};
const sf::Color warningColor{255, 150, 40};

float laneY(Lane lane)
{
    return lane == Lane::Discrete ? discreteLaneY : sweptLaneY;
}

std::string withSpaces(long long number)
{
    // 1000000 -> "1 000 000": speeds are easier to read in a lecture hall.
    std::string digits = std::to_string(number);
    for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3)
        digits.insert(static_cast<std::size_t>(at), " ");
    return digits;
}

sf::Text makeText(const sf::Font& font, const std::string& words, unsigned size, sf::Color color,
                  sf::Vector2f position)
{
    sf::Text text = hitbox::makeText(font, sf::String::fromUtf8(words.begin(), words.end()), size);
    text.setFillColor(color);
    text.setPosition(position);
    return text;
}
} // namespace

PaperLevel::PaperLevel() : nextSpeed(firstSpeed)
{
    wall = {wallX, 95.f, wallThickness, 480.f};
}

void PaperLevel::fire(float speed)
{
    discreteBullet =
        std::make_unique<Bullet>(Lane::Discrete, sf::Vector2f{gunX, discreteLaneY}, speed);
    sweptBullet = std::make_unique<Bullet>(Lane::Swept, sf::Vector2f{gunX, sweptLaneY}, speed);
    ++shotsFired;
}

void PaperLevel::setAutoFire(bool on)
{
    autoFire = on;
}

float PaperLevel::getNextSpeed() const
{
    return nextSpeed;
}

const Bullet* PaperLevel::getBullet(Lane lane) const
{
    return lane == Lane::Discrete ? discreteBullet.get() : sweptBullet.get();
}

LaneScore PaperLevel::getScore(Lane lane) const
{
    return lane == Lane::Discrete ? discreteScore : sweptScore;
}

const hitbox::Box& PaperLevel::getWall() const
{
    return wall;
}

void PaperLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.isPressed(sf::Keyboard::Key::Up))
        nextSpeed = std::min(nextSpeed * speedFactor, maxSpeed);
    if (input.isPressed(sf::Keyboard::Key::Down))
        nextSpeed = std::max(nextSpeed / speedFactor, 50.f);
    if (input.isPressed(sf::Keyboard::Key::A))
        autoFire = !autoFire;
    if (input.isPressed(sf::Keyboard::Key::Space))
        fire(nextSpeed);
}

// [slide:lab04-discrete-vs-swept]
// Discrete: move first, then look. Only the END of the step is ever tested, so a step
// longer than bullet + wall can jump from one side to the other.
void PaperLevel::stepDiscrete(Bullet& bullet, sf::Vector2f step)
{
    bullet.moveBy(step);
    // BEGIN TASK 1: the discrete test - stop the bullet if it overlaps the wall now
    if (hitbox::boxVsBox(hitbox::toBox(bullet.getCollisionBox()), wall))
        bullet.stopInTheWall();
    // END TASK 1
}

// Swept: look along the whole move first; the sweep says WHEN the bullet first touches.
void PaperLevel::stepSwept(Bullet& bullet, sf::Vector2f step)
{
    // BEGIN TASK 2: the swept test - sweep the bullet's box along `step` against the wall
    const hitbox::Hit hit =
        hitbox::sweepBoxVsBox(hitbox::toBox(bullet.getCollisionBox()), hitbox::toVec2(step), wall);
    if (hit)
    {
        bullet.moveBy(step * hit.time); // only as far as the first touch
        bullet.stopInTheWall();
        return;
    }
    // END TASK 2
    bullet.moveBy(step);
}
// [/slide]

bool PaperLevel::stepCouldTunnel(const Bullet& bullet, sf::Vector2f step) const
{
    // BEGIN TASK 3: warn when a step is long enough to tunnel through the wall
    // The discrete test sees an overlap only if some step ENDS with the bullet inside the
    // wall. On one axis, that window is (bullet size + wall size) long: a step at least that
    // long can land before it and then after it.
    const hitbox::Box box = hitbox::toBox(bullet.getCollisionBox());
    return std::abs(step.x) >= box.width + wall.width ||
           std::abs(step.y) >= box.height + wall.height;
    // STARTER TASK 3
    // static_cast<void>(bullet); // (these two lines only keep the compiler quiet:
    // static_cast<void>(step);   //  delete them when you write the test)
    // return false;
    // END TASK 3
}

void PaperLevel::updateBullet(Bullet& bullet, float dt)
{
    if (!bullet.isFlying())
        return;
    const sf::Vector2f step = bullet.getVelocity() * dt;
    bullet.setCouldTunnel(stepCouldTunnel(bullet, step));
    if (bullet.getLane() == Lane::Discrete)
        stepDiscrete(bullet, step);
    else
        stepSwept(bullet, step);

    LaneScore& score = bullet.getLane() == Lane::Discrete ? discreteScore : sweptScore;
    if (bullet.hitTheWall())
        ++score.hits;
    else if (hitbox::toBox(bullet.getCollisionBox()).left > getWorldSize().x)
    {
        bullet.flewAway();
        ++score.misses;
    }
}

void PaperLevel::update(float dt)
{
    if (discreteBullet)
        updateBullet(*discreteBullet, dt);
    if (sweptBullet)
        updateBullet(*sweptBullet, dt);

    const bool shotDone =
        !discreteBullet || (!discreteBullet->isFlying() && !sweptBullet->isFlying());
    if (!autoFire || !shotDone)
        return;
    secondsUntilNextShot -= dt;
    if (secondsUntilNextShot > 0.f && discreteBullet)
        return;
    fire(nextSpeed);
    nextSpeed = nextSpeed * speedFactor > maxSpeed ? firstSpeed : nextSpeed * speedFactor;
    secondsUntilNextShot = pauseBetweenShots;
}

void PaperLevel::drawLane(sf::RenderTarget& target, Lane lane) const
{
    const float y = laneY(lane);
    sf::RectangleShape stripe({getWorldSize().x, 60.f});
    stripe.setPosition({0.f, y - 30.f});
    stripe.setFillColor(laneColor);
    target.draw(stripe);

    sf::RectangleShape gun({50.f, 18.f});
    gun.setPosition({gunX - 55.f, y - 9.f});
    gun.setFillColor(sf::Color(120, 125, 140));
    target.draw(gun);

    const bool discrete = lane == Lane::Discrete;
    const std::string title = discrete
                                  ? "DISCRETE test: is the bullet inside the wall after the step?"
                                  : "SWEPT test: does the whole move of the step touch the wall?";
    target.draw(makeText(font.get(), title, 20, sf::Color::White, {20.f, y - 72.f}));

    const LaneScore score = getScore(lane);
    target.draw(makeText(font.get(), "hits " + std::to_string(score.hits), 26, hitColor,
                         {wallX + 50.f, y - 80.f}));
    target.draw(makeText(font.get(), "misses " + std::to_string(score.misses), 26,
                         score.misses > 0 ? missColor : sf::Color(160, 160, 160),
                         {wallX + 170.f, y - 80.f}));

    const Bullet* bullet = getBullet(lane);
    if (!bullet)
        return;
    // Where the test looked: the bullet after each step. Far apart = fast.
    sf::RectangleShape ghost = *bullet;
    ghost.setFillColor(sf::Color(250, 210, 90, 110));
    for (const sf::Vector2f& position : bullet->getTrail())
    {
        ghost.setPosition(position);
        target.draw(ghost);
    }
    target.draw(*bullet);
    if (!bullet->isFlying())
    {
        const bool hit = bullet->hitTheWall();
        target.draw(makeText(font.get(), hit ? "HIT" : "MISSED", 22, hit ? hitColor : missColor,
                             {wallX + 50.f, y + 34.f}));
    }
    if (!bullet->isFlying() && !bullet->hitTheWall())
        drawJumpOverWall(target, *bullet);

    if (bullet->couldTunnel())
    {
        const float stepLength = bullet->getSpeed() * hitbox::stepSeconds;
        const float window = bullet->getSize().x + wall.width;
        target.draw(makeText(font.get(),
                             "CAN TUNNEL: one step is " + withSpaces(std::lround(stepLength)) +
                                 " px, bullet + wall only " + std::to_string(std::lround(window)) +
                                 " px",
                             18, warningColor, {gunX, y + 34.f}));
    }
}

// A missed bullet: show the one step that carried it from one side of the wall to the other.
void PaperLevel::drawJumpOverWall(sf::RenderTarget& target, const Bullet& bullet) const
{
    const std::vector<sf::Vector2f>& trail = bullet.getTrail();
    for (std::size_t i = 1; i < trail.size(); ++i)
    {
        if (trail[i - 1].x >= wall.left || trail[i].x < wall.left)
            continue;
        const float y = trail[i].y - 14.f;
        sf::RectangleShape jump({trail[i].x - trail[i - 1].x, 3.f});
        jump.setPosition({trail[i - 1].x, y});
        jump.setFillColor(missColor);
        target.draw(jump);
        // render() always has a window, so measuring text is safe here.
        sf::Text label = makeText(font.get(), "passed through unseen", 16, missColor, {0.f, 0.f});
        label.setPosition(
            {wall.left - 12.f - hitbox::toBox(label.getLocalBounds()).width, y + 48.f});
        target.draw(label);
        return;
    }
}

void PaperLevel::render(sf::RenderTarget& target) const
{
    drawLane(target, Lane::Discrete);
    drawLane(target, Lane::Swept);

    sf::RectangleShape paper({wall.width, wall.height});
    paper.setPosition({wall.left, wall.top});
    paper.setFillColor(paperColor);
    target.draw(paper);

    std::string shot = "Bullet through paper";
    if (const Bullet* bullet = getBullet(Lane::Discrete))
    {
        char perStep[32];
        std::snprintf(perStep, sizeof(perStep), "%.1f", bullet->getSpeed() * hitbox::stepSeconds);
        shot += "   -   shot " + std::to_string(shotsFired) + ": " +
                withSpaces(std::lround(bullet->getSpeed())) + " px/s = " + perStep + " px per step";
    }
    target.draw(makeText(font.get(), shot, 24, sf::Color::White, {20.f, 16.f}));
    target.draw(makeText(font.get(),
                         "wall: 4 px   bullet: 12 px   faint boxes: where each step ended", 16,
                         sf::Color(170, 170, 180), {20.f, 600.f}));
}

void PaperLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    debug.box(wall, hitbox::DebugRenderer::freeColor);
    for (Lane lane : {Lane::Discrete, Lane::Swept})
    {
        const Bullet* bullet = getBullet(lane);
        if (!bullet)
            continue;
        // The swept hull: everything the last step passed over. Orange when that step was
        // long enough to tunnel.
        debug.box(hitbox::toBox(bullet->getLastSweptArea()),
                  bullet->couldTunnel() ? warningColor : hitbox::DebugRenderer::hintColor);
        debug.box(hitbox::toBox(bullet->getCollisionBox()),
                  bullet->hitTheWall() ? hitbox::DebugRenderer::overlappingColor
                                       : hitbox::DebugRenderer::freeColor);
    }
}

std::string PaperLevel::getHelpText() const
{
    return "Space fire   Up/Down speed   A auto-fire on/off";
}

std::string PaperLevel::describeState() const
{
    return std::to_string(shotsFired) + " shots | discrete: " + std::to_string(discreteScore.hits) +
           " hits " + std::to_string(discreteScore.misses) +
           " misses | swept: " + std::to_string(sweptScore.hits) + " hits " +
           std::to_string(sweptScore.misses) + " misses";
}
