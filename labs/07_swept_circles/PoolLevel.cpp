#include "PoolLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Response.h"
#include "hitbox/geometry/SweptCircle.h"
#include "hitbox/sfml/Conversions.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <utility>

namespace
{
const float ballRadius = 14.f;
const float cushionRestitution = 0.9f; // a cushion keeps 90 % of the speed into it
const float rollingDrag = 0.6f;        // per second: speed falls to 55 % after one second
const float stopSpeed = 5.f;           // slower than this (px/s): the ball stops
const int maxEventsPerStep = 64;       // a break can need many collisions in one step
const std::size_t maxImpactsShown = 6;
const std::size_t cueTrailLength = 240;

const hitbox::Box labTable{120.f, 110.f, 960.f, 480.f};
const float cushionThickness = 36.f;

std::vector<Ball> rackedBalls()
{
    std::vector<Ball> rack;
    // Ball 0: the cue ball, on its way to the rack at break speed.
    rack.push_back({{{300.f, 350.f}, ballRadius}, {6000.f, 0.f}, sf::Color::White});
    const sf::Color colors[] = {{250, 200, 40}, {40, 90, 220}, {220, 50, 50}, {120, 50, 160},
                                {250, 130, 30}, {30, 150, 80}, {130, 40, 40}, {30, 30, 30},
                                {250, 200, 40}, {40, 90, 220}};
    // A loose triangle: 10 px gaps, so the break spreads the balls instead of passing the
    // whole push down a tight chain to the back row (what ideal elastic balls would do).
    const float spacing = 2.f * ballRadius + 10.f;
    int index = 0;
    for (int row = 0; row < 4; ++row)
        for (int place = 0; place <= row; ++place)
        {
            const hitbox::Vec2 center{760.f + row * spacing * 0.866f,
                                      350.f + (place - row / 2.f) * spacing};
            rack.push_back({{center, ballRadius}, {0.f, 0.f}, colors[index++]});
        }
    return rack;
}

float lengthSquared(hitbox::Vec2 vector)
{
    return hitbox::dot(vector, vector);
}
} // namespace

PoolLevel::PoolLevel() : PoolLevel(rackedBalls(), labTable) {}

PoolLevel::PoolLevel(std::vector<Ball> startBalls, hitbox::Box playingArea)
    : balls(std::move(startBalls)), table(playingArea), mouse(900.f, 350.f)
{
    const float t = cushionThickness;
    cushions = {
        {table.left - t, table.top - t, table.width + 2.f * t, t},            // top
        {table.left - t, table.top + table.height, table.width + 2.f * t, t}, // bottom
        {table.left - t, table.top, t, table.height},                         // left
        {table.left + table.width, table.top, t, table.height},               // right
    };
    if (!balls.empty())
        cueTrail.push_back(balls[0].shape.center);
}

void PoolLevel::setSwept(bool on)
{
    swept = on;
}

void PoolLevel::setFriction(bool on)
{
    friction = on;
}

void PoolLevel::shoot(hitbox::Vec2 target, float speed)
{
    if (balls.empty())
        return;
    balls[0].velocity = hitbox::unitVectorOr(target - balls[0].shape.center, {1.f, 0.f}) * speed;
    cueTrail.assign(1, balls[0].shape.center);
    cueImpact = {};
}

const std::vector<Ball>& PoolLevel::getBalls() const
{
    return balls;
}

const std::vector<hitbox::Box>& PoolLevel::getCushions() const
{
    return cushions;
}

hitbox::Box PoolLevel::getTable() const
{
    return table;
}

void PoolLevel::handleInput(const hitbox::Input& input, float)
{
    mouse = hitbox::toVec2(input.getMousePosition());
    if (input.isLeftMousePressed() || input.isPressed(sf::Keyboard::Key::Space))
        shoot(mouse, shotSpeed);
    if (input.isPressed(sf::Keyboard::Key::Up))
        shotSpeed = std::fmin(shotSpeed * 1.5f, 100000.f);
    if (input.isPressed(sf::Keyboard::Key::Down))
        shotSpeed = std::fmax(shotSpeed / 1.5f, 100.f);
    if (input.isPressed(sf::Keyboard::Key::D))
        swept = !swept;
    if (input.isPressed(sf::Keyboard::Key::R))
    {
        balls = rackedBalls();
        cueTrail.assign(1, balls[0].shape.center);
        impacts.clear();
        cueImpact = {};
    }
}

bool PoolLevel::isNewCollision(const hitbox::Hit& hit, hitbox::Vec2 relativeVelocity)
{
    // After a bounce the two shapes touch, and float rounding can leave them overlapping by
    // a hair. The sweep then reports "started inside" - but if they are already moving
    // apart, the bounce has happened: counting it again would stop the step forever.
    if (!hit)
        return false;
    return !hit.startedInside || hitbox::dot(relativeVelocity, hit.normal) < 0.f;
}

BallEvent PoolLevel::findFirstEvent(float seconds) const
{
    BallEvent first;
    // BEGIN TASK 1: the earliest ball-ball time of impact
    // Every pair, both moving: only their relative move matters (the quadratic of
    // Ericson, Real-Time Collision Detection, 5.5 "Dynamic intersection tests").
    for (std::size_t a = 0; a < balls.size(); ++a)
        for (std::size_t b = a + 1; b < balls.size(); ++b)
        {
            const hitbox::Hit meeting =
                hitbox::sweepCircleVsMovingCircle(balls[a].shape, balls[a].velocity * seconds,
                                                  balls[b].shape, balls[b].velocity * seconds);
            const hitbox::Vec2 closing = balls[a].velocity - balls[b].velocity;
            if (isNewCollision(meeting, closing) && meeting.time < first.time)
                first = {true, meeting.time, a, b, -1, meeting.normal};
        }
    // STARTER TASK 1
    // static_cast<void>(seconds); // (only keeps the compiler quiet: delete it)
    // END TASK 1
    // BEGIN TASK 3: balls against the cushions
    for (std::size_t a = 0; a < balls.size(); ++a)
        for (std::size_t c = 0; c < cushions.size(); ++c)
        {
            const hitbox::Hit bump =
                hitbox::sweepCircleVsBox(balls[a].shape, balls[a].velocity * seconds, cushions[c]);
            if (isNewCollision(bump, balls[a].velocity) && bump.time < first.time)
                first = {true, bump.time, a, a, static_cast<int>(c), bump.normal};
        }
    // END TASK 3
    return first;
}

// [slide:lab07-toi-pool]
void PoolLevel::stepSwept(float dt)
{
    float secondsLeft = dt;
    for (int event = 0; event < maxEventsPerStep && secondsLeft > 0.f; ++event)
    {
        const BallEvent next = findFirstEvent(secondsLeft);
        // Everyone moves up to the first collision (or to the end of the step)...
        for (Ball& ball : balls)
            ball.advance(secondsLeft * next.time);
        if (!next.hit)
            return;
        // ...that one collision is answered, and the rest of the step goes round again.
        answer(next);
        secondsLeft *= 1.f - next.time;
        if (next.cushion < 0 && (next.first == 0 || next.second == 0))
            cueImpact = {true, balls[0].shape.center, 1.f - secondsLeft / dt};
    }
    // Out of events: the rest of this step is dropped (the balls lose a moment of motion,
    // but nothing passes through anything).
}
// [/slide]

std::pair<hitbox::Vec2, hitbox::Vec2>
PoolLevel::bounceBalls(hitbox::Vec2 first, hitbox::Vec2 second, hitbox::Vec2 normal)
{
    // BEGIN TASK 2: equal balls swap their speeds along the normal
    // Only the part of the velocity along the line between the centres changes; equal
    // masses simply exchange that part (an elastic response with m1 == m2).
    const float closing = hitbox::dot(first - second, normal);
    if (closing >= 0.f)
        return {first, second}; // already moving apart
    return {first - normal * closing, second + normal * closing};
    // STARTER TASK 2
    // static_cast<void>(normal); // (only keeps the compiler quiet: delete it)
    // return {first, second};
    // END TASK 2
}

void PoolLevel::answer(const BallEvent& event)
{
    Ball& ball = balls[event.first];
    if (event.cushion >= 0)
    {
        ball.velocity = hitbox::bounceVelocity(ball.velocity, event.normal, cushionRestitution);
        return;
    }
    Ball& other = balls[event.second];
    const auto [firstVelocity, secondVelocity] =
        bounceBalls(ball.velocity, other.velocity, event.normal);
    ball.velocity = firstVelocity;
    other.velocity = secondVelocity;
    impacts.push_back({ball.shape, other.shape, event.normal});
    if (impacts.size() > maxImpactsShown)
        impacts.erase(impacts.begin());
}

// The "before": move everything the whole step, then push overlapping balls apart. A ball
// that moves more than its own width in a step can jump right over another.
void PoolLevel::stepDiscrete(float dt)
{
    for (Ball& ball : balls)
        ball.advance(dt);
    for (std::size_t a = 0; a < balls.size(); ++a)
    {
        for (std::size_t b = a + 1; b < balls.size(); ++b)
        {
            const hitbox::Contact contact =
                hitbox::circleVsCircleContact(balls[a].shape, balls[b].shape);
            if (!contact)
                continue;
            balls[a].shape.center += contact.normal * (contact.depth / 2.f);
            balls[b].shape.center -= contact.normal * (contact.depth / 2.f);
            answer({true, 0.f, a, b, -1, contact.normal});
        }
        for (std::size_t c = 0; c < cushions.size(); ++c)
        {
            const hitbox::Contact contact = hitbox::circleVsBoxContact(balls[a].shape, cushions[c]);
            if (!contact)
                continue;
            balls[a].shape.center += hitbox::pushOutOffset(contact);
            answer({true, 0.f, a, a, static_cast<int>(c), contact.normal});
        }
    }
}

void PoolLevel::update(float dt)
{
    if (swept)
        stepSwept(dt);
    else
        stepDiscrete(dt);

    if (friction)
        for (Ball& ball : balls)
        {
            ball.velocity *= std::fmax(0.f, 1.f - rollingDrag * dt);
            if (lengthSquared(ball.velocity) < stopSpeed * stopSpeed)
                ball.velocity = {0.f, 0.f};
        }
    if (!balls.empty())
    {
        cueTrail.push_back(balls[0].shape.center);
        if (cueTrail.size() > cueTrailLength)
            cueTrail.erase(cueTrail.begin());
    }
}

void PoolLevel::render(sf::RenderTarget& target) const
{
    sf::RectangleShape felt({table.width, table.height});
    felt.setPosition({table.left, table.top});
    felt.setFillColor(sf::Color(30, 110, 60));
    target.draw(felt);
    for (const hitbox::Box& cushion : cushions)
    {
        sf::RectangleShape drawn({cushion.width, cushion.height});
        drawn.setPosition({cushion.left, cushion.top});
        drawn.setFillColor(sf::Color(110, 65, 35));
        target.draw(drawn);
    }

    // The cue ball after each step: far apart = fast.
    sf::CircleShape dot(3.f);
    dot.setOrigin({3.f, 3.f});
    dot.setFillColor(sf::Color(255, 255, 255, 110));
    for (const hitbox::Vec2& point : cueTrail)
    {
        dot.setPosition(hitbox::toSfml(point));
        target.draw(dot);
    }

    // Where the latest impacts happened: both balls at the moment they touched.
    for (const Impact& impact : impacts)
        for (const hitbox::Circle& circle : {impact.first, impact.second})
        {
            sf::CircleShape ghost(circle.radius, 32);
            ghost.setOrigin({circle.radius, circle.radius});
            ghost.setPosition(hitbox::toSfml(circle.center));
            ghost.setFillColor(sf::Color::Transparent);
            ghost.setOutlineColor(sf::Color(255, 240, 120, 150));
            ghost.setOutlineThickness(1.5f);
            target.draw(ghost);
        }

    for (const Ball& ball : balls)
    {
        sf::CircleShape drawn(ball.shape.radius, 32);
        drawn.setOrigin({ball.shape.radius, ball.shape.radius});
        drawn.setPosition(hitbox::toSfml(ball.shape.center));
        drawn.setFillColor(ball.color);
        target.draw(drawn);
    }

    if (cueImpact.happened)
    {
        char when[96];
        std::snprintf(when, sizeof(when), "cue ball stopped where it touched: t = %.2f of its step",
                      cueImpact.stepFraction);
        sf::Text label = hitbox::makeText(font.get(), when, 16);
        label.setFillColor(sf::Color::White);
        label.setOutlineColor(sf::Color::Black);
        label.setOutlineThickness(1.5f);
        label.setPosition(hitbox::toSfml(cueImpact.where + hitbox::Vec2{-470.f, 18.f}));
        target.draw(label);
    }

    float fastest = 0.f;
    for (const Ball& ball : balls)
        fastest = std::fmax(fastest, hitbox::length(ball.velocity));
    const std::string mode =
        swept ? "TIME OF IMPACT: first collision first, then the rest of the step"
              : "DISCRETE: move, then look for overlaps (press D)";
    sf::Text title = hitbox::makeText(font.get(), mode, 22);
    title.setFillColor(swept ? sf::Color(140, 240, 160) : sf::Color(255, 110, 90));
    title.setPosition({20.f, 14.f});
    target.draw(title);
    const long perStep = std::lround(fastest * hitbox::stepSeconds);
    sf::Text speed = hitbox::makeText(
        font.get(),
        "fastest ball: " + std::to_string(perStep) + " px per step (a ball is " +
            std::to_string(std::lround(2.f * ballRadius)) +
            " px wide)   next shot: " + std::to_string(std::lround(shotSpeed)) + " px/s",
        16);
    speed.setFillColor(perStep > 2.f * ballRadius ? sf::Color(255, 170, 60)
                                                  : sf::Color(200, 200, 200));
    speed.setPosition({20.f, 44.f});
    target.draw(speed);
    sf::Text legend =
        hitbox::makeText(font.get(),
                         "white dots: the cue ball after each step   yellow rings: balls at the "
                         "moment of impact",
                         16);
    legend.setFillColor(sf::Color(200, 200, 200));
    legend.setPosition({20.f, 630.f});
    target.draw(legend);
}

void PoolLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    for (const hitbox::Box& cushion : cushions)
        debug.box(cushion, hitbox::DebugRenderer::freeColor);
    for (const Ball& ball : balls)
    {
        debug.circle(ball.shape, hitbox::DebugRenderer::freeColor);
        // Where the ball will be in four steps.
        debug.arrow(ball.shape.center,
                    ball.shape.center + ball.velocity * (4.f * hitbox::stepSeconds),
                    hitbox::DebugRenderer::velocityColor);
    }
    for (const Impact& impact : impacts)
    {
        const hitbox::Vec2 touch = impact.second.center + impact.normal * impact.second.radius;
        debug.arrow(touch, touch + impact.normal * 30.f, hitbox::DebugRenderer::normalColor);
    }
}

std::string PoolLevel::getHelpText() const
{
    return "Click/Space shoot at the mouse   Up/Down shot speed   D discrete/swept   R rack";
}

std::string PoolLevel::describeState() const
{
    std::size_t onTable = 0;
    for (const Ball& ball : balls)
        onTable += hitbox::pointInBox(ball.shape.center, table) ? 1 : 0;
    std::size_t moving = 0;
    for (const Ball& ball : balls)
        moving += lengthSquared(ball.velocity) > 0.f ? 1 : 0;
    return std::string(swept ? "swept" : "discrete") + ": " + std::to_string(onTable) + " of " +
           std::to_string(balls.size()) + " balls on the table, " + std::to_string(moving) +
           " moving";
}

using PoolSnapshot = hitbox::WholeLevelCopy<PoolLevel>; // Level.h: a copy of the whole level

std::unique_ptr<hitbox::LevelState> PoolLevel::saveState() const
{
    const std::size_t held =
        sizeof(PoolSnapshot) + balls.size() * sizeof(Ball) + cushions.size() * sizeof(hitbox::Box) +
        cueTrail.size() * sizeof(hitbox::Vec2) + impacts.size() * sizeof(Impact);
    return std::make_unique<PoolSnapshot>(*this, held);
}

void PoolLevel::restoreState(const hitbox::LevelState& state)
{
    *this = static_cast<const PoolSnapshot&>(state).level;
}
