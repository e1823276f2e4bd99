#include "RayLevel.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace
{
const float playerSpeed = 300.f; // pixels per second
const sf::Vector2f playerSize{32.f, 32.f};
const float tileSize = 40.f;
const std::size_t trailLength = 900;

const sf::Color solidColor{70, 90, 140};
const sf::Color tileColor{90, 110, 150};
const sf::Color playerColor{240, 200, 80};
const sf::Color rayColor{255, 240, 160};
const sf::Color hitColor{255, 90, 80};

void drawThickLine(sf::RenderTarget& target, sf::Vector2f from, sf::Vector2f to, float thickness,
                   sf::Color color)
{
    const sf::Vector2f along = to - from;
    const float length = std::sqrt(along.x * along.x + along.y * along.y);
    sf::RectangleShape line({length, thickness});
    line.setOrigin({0.f, thickness / 2.f});
    line.setPosition(from);
    hitbox::setRotationDegrees(line, std::atan2(along.y, along.x) * 180.f / 3.14159265f);
    line.setFillColor(color);
    target.draw(line);
}

float dot(sf::Vector2f a, sf::Vector2f b)
{
    return a.x * b.x + a.y * b.y;
}

// The lab's field: borders, a floor and a right wall made of separate tiles (their seams
// are what snags a sliding box), and a few boxes in the middle for the ray to hit.
std::vector<sf::FloatRect> labField()
{
    std::vector<sf::FloatRect> field = {
        {0.f, 40.f, 40.f, 600.f},   // left border
        {40.f, 40.f, 1120.f, 20.f}, // top border
        {230.f, 170.f, 120.f, 80.f}, {470.f, 120.f, 60.f, 180.f}, {700.f, 190.f, 160.f, 50.f},
        {330.f, 360.f, 90.f, 90.f},  {600.f, 400.f, 200.f, 30.f}, {900.f, 330.f, 60.f, 120.f},
    };
    // Floor tiles, stored left to right as a level file would list them.
    for (float x = 40.f; x < 1120.f; x += tileSize)
        field.push_back({x, 600.f, tileSize, tileSize});
    // Right wall tiles, stored top to bottom.
    for (float y = 60.f; y < 600.f; y += tileSize)
        field.push_back({1120.f, y, tileSize, tileSize});
    return field;
}
} // namespace

RayLevel::RayLevel() : RayLevel(labField(), {1000.f, 560.f}) {}

RayLevel::RayLevel(std::vector<sf::FloatRect> solidBoxes, sf::Vector2f playerStart)
    : solids(std::move(solidBoxes)), mouse(760.f, 110.f), font(hitbox::loadFont())
{
    player.setSize(playerSize);
    player.setPosition(playerStart);
    player.setFillColor(playerColor);
    trail.push_back(player.getPosition() + playerSize / 2.f);
}

void RayLevel::handleInput(const Input& input, float)
{
    if (input.getMousePosition() != lastMouseReading)
        mouse = input.getMousePosition();
    lastMouseReading = input.getMousePosition();

    sf::Vector2f direction;
    if (input.isKeyDown(sf::Keyboard::Key::A) || input.isKeyDown(sf::Keyboard::Key::Left))
        direction.x -= 1.f;
    if (input.isKeyDown(sf::Keyboard::Key::D) || input.isKeyDown(sf::Keyboard::Key::Right))
        direction.x += 1.f;
    if (input.isKeyDown(sf::Keyboard::Key::W) || input.isKeyDown(sf::Keyboard::Key::Up))
        direction.y -= 1.f;
    if (input.isKeyDown(sf::Keyboard::Key::S) || input.isKeyDown(sf::Keyboard::Key::Down))
        direction.y += 1.f;
    // The keys take over from the demo (or from setMoveDirection) once one is pressed.
    if (direction != sf::Vector2f{})
        keyboardControl = true;
    if (keyboardControl)
        moveDirection = direction;
    if (input.isPressed(sf::Keyboard::Key::T))
        timeOrder = !timeOrder;
}

void RayLevel::setTimeOrder(bool on)
{
    timeOrder = on;
}

bool RayLevel::usesTimeOrder() const
{
    return timeOrder;
}

void RayLevel::setMoveDirection(sf::Vector2f direction)
{
    keyboardControl = false;
    moveDirection = direction;
}

const GameObject& RayLevel::getPlayer() const
{
    return player;
}

const std::vector<sf::FloatRect>& RayLevel::getSolids() const
{
    return solids;
}

const RayHit& RayLevel::getRay() const
{
    return ray;
}

const std::vector<SolidHit>& RayLevel::getLastHits() const
{
    return lastHits;
}

bool RayLevel::isStuck() const
{
    return stuck;
}

// [slide:lab05-ray-nearest-hit]
RayHit RayLevel::castRay(sf::Vector2f from, sf::Vector2f to) const
{
    RayHit nearest;
    nearest.start = from;
    nearest.end = to;
    // BEGIN TASK 1: find the nearest box the ray hits
    // Every box the segment crosses answers with a time along it; the smallest time is the
    // first thing the ray meets. (Stopping at the first box in the list would let a far box
    // hide a near one.)
    for (std::size_t i = 0; i < solids.size(); ++i)
    {
        const hitbox::Hit hit = hitbox::segmentVsBox(from, to, solids[i]);
        if (!hit || (nearest.hit && hit.time >= nearest.time))
            continue;
        nearest.hit = true;
        nearest.time = hit.time;
        nearest.end = hit.point;
        nearest.normal = hit.normal;
        nearest.boxIndex = static_cast<int>(i);
    }
    // END TASK 1
    return nearest;
}
// [/slide]

std::vector<SolidHit> RayLevel::solidsInTheWay(sf::Vector2f move) const
{
    std::vector<SolidHit> inTheWay;
    for (std::size_t i = 0; i < solids.size(); ++i)
    {
        const hitbox::Hit hit = hitbox::sweepBoxVsBox(player.getCollisionBox(), move, solids[i]);
        if (hit)
            inTheWay.push_back({i, hit.time});
    }
    return inTheWay;
}

bool RayLevel::isNearer(const SolidHit& a, const SolidHit& b) const
{
    const sf::Vector2f center = hitbox::centerOf(player.getCollisionBox());
    const sf::Vector2f toA = hitbox::centerOf(solids[a.index]) - center;
    const sf::Vector2f toB = hitbox::centerOf(solids[b.index]) - center;
    return dot(toA, toA) < dot(toB, toB);
}

// [slide:lab05-slide-time-order]
void RayLevel::movePlayer(sf::Vector2f velocity, float dt)
{
    lastHits = solidsInTheWay(velocity * dt); // every solid this move runs into, and when
    // BEGIN TASK 3: handle the nearest contact first (ties: the nearer solid)
    if (timeOrder)
        std::sort(lastHits.begin(), lastHits.end(),
                  [&](const SolidHit& a, const SolidHit& b)
                  { return a.time != b.time ? a.time < b.time : isNearer(a, b); });
    // END TASK 3
    // BEGIN TASK 2: slide - remove the part of the velocity that goes into each surface
    for (const SolidHit& candidate : lastHits)
    {
        const hitbox::Hit now = // sweep again: earlier answers may have steered clear
            hitbox::sweepBoxVsBox(player.getCollisionBox(), velocity * dt, solids[candidate.index]);
        if (!now)
            continue;
        if (now.startedInside)
            player.move(now.normal * now.depth); // already overlapping: push out first
        const float into = dot(velocity, now.normal);
        if (into < 0.f)
            velocity -= now.normal * into * (1.f - now.time); // keep only the part up to the touch
    }
    // END TASK 2
    player.move(velocity * dt);
}
// [/slide]

void RayLevel::update(float dt)
{
    sf::Vector2f direction = moveDirection;
    const float length = std::sqrt(dot(direction, direction));
    if (length > 0.f)
        direction /= length;
    player.setVelocity(direction * playerSpeed);
    const sf::Vector2f before = player.getPosition();
    movePlayer(player.getVelocity(), dt);
    // Wanting to move but barely moving: snagged (or pressed into a corner).
    const sf::Vector2f moved = player.getPosition() - before;
    stuck = length > 0.f && dot(moved, moved) < 0.01f * playerSpeed * dt * playerSpeed * dt;

    trail.push_back(player.getPosition() + playerSize / 2.f);
    if (trail.size() > trailLength)
        trail.erase(trail.begin());

    ray = castRay(player.getPosition() + playerSize / 2.f, mouse);
}

void RayLevel::render(sf::RenderTarget& target) const
{
    const std::size_t firstTile = solids.size() >= 2 ? 8 : solids.size();
    for (std::size_t i = 0; i < solids.size(); ++i)
    {
        sf::RectangleShape box({solids[i].width, solids[i].height});
        box.setPosition({solids[i].left, solids[i].top});
        const bool isTile = i >= firstTile;
        box.setFillColor(static_cast<int>(i) == ray.boxIndex ? sf::Color(120, 80, 110)
                         : isTile                            ? tileColor
                                                             : solidColor);
        if (isTile)
        {
            // Draw the seams: the floor is many boxes, not one.
            box.setOutlineColor(sf::Color(40, 50, 70));
            box.setOutlineThickness(-1.f);
        }
        target.draw(box);
    }

    sf::VertexArray path(sf::PrimitiveType::LineStrip);
    for (const sf::Vector2f& point : trail)
        path.append(sf::Vertex{point, sf::Color(240, 200, 80, 120)});
    target.draw(path);
    target.draw(player);

    // The ray: bright up to the hit, faint beyond it (the part the wall hides).
    drawThickLine(target, ray.start, ray.end, 3.f, rayColor);
    if (ray.hit)
    {
        drawThickLine(target, ray.end, mouse, 2.f, sf::Color(255, 240, 160, 60));
        drawThickLine(target, ray.end, ray.end + ray.normal * 45.f, 3.f, hitColor);
        sf::CircleShape dot(6.f);
        dot.setOrigin({6.f, 6.f});
        dot.setPosition(ray.end);
        dot.setFillColor(hitColor);
        target.draw(dot);
    }
    if (stuck)
    {
        sf::Text stuckText = hitbox::makeText(font, "stuck!", 18);
        stuckText.setFillColor(hitColor);
        stuckText.setPosition(player.getPosition() + sf::Vector2f{-8.f, -30.f});
        target.draw(stuckText);
    }

    const std::string order = timeOrder ? "ON  (nearest contact first: slides over the seams)"
                                        : "OFF (list order: snags on a seam)";
    sf::Text status = hitbox::makeText(font, "Time order " + order, 20);
    status.setFillColor(timeOrder ? sf::Color(120, 230, 140) : hitColor);
    status.setPosition({60.f, 4.f});
    target.draw(status);
    sf::Text rayText = hitbox::makeText(
        font, ray.hit ? "ray: nearest hit, normal drawn in red" : "ray: no hit", 16);
    rayText.setFillColor(rayColor);
    rayText.setPosition({700.f, 8.f});
    target.draw(rayText);
}

void RayLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    for (const SolidHit& hit : lastHits)
        debug.box(solids[hit.index], hitbox::DebugRenderer::touchingColor);
    // The swept area of the next quarter second, and the player's velocity.
    debug.objectBox(player, !lastHits.empty());
    if (ray.hit)
        debug.box(solids[static_cast<std::size_t>(ray.boxIndex)], hitbox::DebugRenderer::hintColor);
    debug.cross(ray.end, 8.f, hitbox::DebugRenderer::normalColor);
}

std::string RayLevel::getHelpText() const
{
    return "Mouse aims the ray   WASD/arrows move   T time order on/off";
}

std::string RayLevel::describeState() const
{
    const sf::Vector2f position = player.getPosition();
    return "player at (" + std::to_string(std::lround(position.x)) + ", " +
           std::to_string(std::lround(position.y)) + "), time order " + (timeOrder ? "on" : "off") +
           ", ray " + (ray.hit ? "hits box " + std::to_string(ray.boxIndex) : "hits nothing");
}
