#include "RayLevel.h"

#include "RayCircle.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Resolve.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/sfml/Graphics.h"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
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
    hitbox::setRotationDegrees(line, std::atan2(along.y, along.x) * 180.f / hitbox::pi);
    line.setFillColor(color);
    target.draw(line);
}

// The lab's field: borders, a floor and a right wall made of separate tiles (their seams
// are what snags a sliding box), and a few boxes in the middle for the ray to hit.
std::vector<hitbox::Box> labField()
{
    std::vector<hitbox::Box> field = {
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

RayLevel::RayLevel() : RayLevel(labField(), {1000.f, 560.f})
{
    pillars = {{{140.f, 300.f}, 40.f}, {{620.f, 320.f}, 30.f}};
}

RayLevel::RayLevel(std::vector<hitbox::Box> solidBoxes, sf::Vector2f playerStart)
    : solids(std::move(solidBoxes)), mouse(760.f, 110.f)
{
    player.setSize(playerSize);
    player.setPosition(playerStart);
    player.setFillColor(playerColor);
    trail.push_back(player.getPosition() + playerSize / 2.f);
}

void RayLevel::handleInput(const hitbox::Input& input, float)
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

const hitbox::GameObject& RayLevel::getPlayer() const
{
    return player;
}

const std::vector<hitbox::Box>& RayLevel::getSolids() const
{
    return solids;
}

const std::vector<hitbox::Circle>& RayLevel::getPillars() const
{
    return pillars;
}

const RayHit& RayLevel::getRay() const
{
    return ray;
}

const std::vector<hitbox::Hit>& RayLevel::getLastHits() const
{
    return lastHits;
}

bool RayLevel::isStuck() const
{
    return stuck;
}

// [slide:lab05-ray-nearest-hit]
RayHit RayLevel::castRay(hitbox::Vec2 from, hitbox::Vec2 to) const
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

// [slide:lab05-move-and-slide]
void RayLevel::movePlayer(sf::Vector2f velocity, float dt)
{
    // BEGIN TASK 2: move the player's box with hitbox::moveBoxAndSlide, then follow it
    // moveBoxAndSlide sweeps the whole move against every solid, handles the hits nearest in
    // time first (unless timeOrder is off) and removes the part of the velocity that goes
    // into each surface: the box ends touching walls and keeps sliding along them.
    const hitbox::Box box = hitbox::toBox(player.getCollisionBox());
    const hitbox::MoveResult moved =
        hitbox::moveBoxAndSlide(box, hitbox::toVec2(velocity), dt, solids, timeOrder);
    player.move({moved.box.left - box.left, moved.box.top - box.top});
    lastHits = moved.hits;
    // STARTER TASK 2
    // player.move(velocity * dt); // no collision yet: the player walks through walls
    // lastHits.clear();
    // END TASK 2
}
// [/slide]

// [slide:lab05-stuck]
bool isSnagged(sf::Vector2f wanted, sf::Vector2f moved)
{
    // BEGIN TASK 3: moving less than a tenth of the wanted distance is stuck
    // Compare squared lengths: no square root needed. Not wanting to move is never stuck.
    const float wantedSquared = wanted.x * wanted.x + wanted.y * wanted.y;
    const float movedSquared = moved.x * moved.x + moved.y * moved.y;
    return wantedSquared > 0.f && movedSquared < 0.01f * wantedSquared;
    // STARTER TASK 3
    // (void)wanted;
    // (void)moved;
    // return false;
    // END TASK 3
}
// [/slide]

void RayLevel::update(float dt)
{
    sf::Vector2f direction = moveDirection;
    const float length = hitbox::length(hitbox::toVec2(direction));
    if (length > 0.f)
        direction /= length;
    player.setVelocity(direction * playerSpeed);
    const sf::Vector2f before = player.getPosition();
    movePlayer(player.getVelocity(), dt);
    stuck = isSnagged(player.getVelocity() * dt, player.getPosition() - before);

    trail.push_back(player.getPosition() + playerSize / 2.f);
    if (trail.size() > trailLength)
        trail.erase(trail.begin());

    const hitbox::Vec2 from = hitbox::toVec2(player.getPosition() + playerSize / 2.f);
    ray = stopAtPillars(castRay(from, hitbox::toVec2(mouse)), hitbox::toVec2(mouse));
}

RayHit RayLevel::stopAtPillars(RayHit boxHit, hitbox::Vec2 to) const
{
    RayHit nearest = boxHit;
    for (std::size_t i = 0; i < pillars.size(); ++i)
    {
        const float time = rayCircleTime(boxHit.start, to, pillars[i]);
        if (time < 0.f || time >= nearest.time)
            continue;
        nearest.hit = true;
        nearest.time = time;
        nearest.end = boxHit.start + (to - boxHit.start) * time;
        nearest.normal = hitbox::unitVectorOr(nearest.end - pillars[i].center, {-1.f, 0.f});
        nearest.boxIndex = -1;
        nearest.pillarIndex = static_cast<int>(i);
    }
    return nearest;
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

    for (std::size_t i = 0; i < pillars.size(); ++i)
    {
        sf::CircleShape pillar(pillars[i].radius);
        pillar.setOrigin({pillars[i].radius, pillars[i].radius});
        pillar.setPosition(hitbox::toSfml(pillars[i].center));
        pillar.setFillColor(static_cast<int>(i) == ray.pillarIndex ? sf::Color(120, 80, 110)
                                                                   : solidColor);
        target.draw(pillar);
    }

    sf::VertexArray path(sf::PrimitiveType::LineStrip);
    for (const sf::Vector2f& point : trail)
        path.append(sf::Vertex{point, sf::Color(240, 200, 80, 120)});
    target.draw(path);
    target.draw(player);

    // The ray: bright up to the hit, faint beyond it (the part the wall hides).
    const sf::Vector2f rayStart = hitbox::toSfml(ray.start);
    const sf::Vector2f rayEnd = hitbox::toSfml(ray.end);
    drawThickLine(target, rayStart, rayEnd, 3.f, rayColor);
    if (ray.hit)
    {
        drawThickLine(target, rayEnd, mouse, 2.f, sf::Color(255, 240, 160, 60));
        drawThickLine(target, rayEnd, hitbox::toSfml(ray.end + ray.normal * 45.f), 3.f, hitColor);
        sf::CircleShape dot(6.f);
        dot.setOrigin({6.f, 6.f});
        dot.setPosition(rayEnd);
        dot.setFillColor(hitColor);
        target.draw(dot);
    }
    if (stuck)
    {
        sf::Text stuckText = hitbox::makeText(font.get(), "stuck!", 18);
        stuckText.setFillColor(hitColor);
        stuckText.setPosition(player.getPosition() + sf::Vector2f{-8.f, -30.f});
        target.draw(stuckText);
    }

    const std::string order = timeOrder ? "ON  (nearest contact first: slides over the seams)"
                                        : "OFF (list order: snags on a seam)";
    sf::Text status = hitbox::makeText(font.get(), "Time order " + order, 20);
    status.setFillColor(timeOrder ? sf::Color(120, 230, 140) : hitColor);
    status.setPosition({60.f, 4.f});
    target.draw(status);
    sf::Text rayText = hitbox::makeText(
        font.get(), ray.hit ? "ray: nearest hit, normal drawn in red" : "ray: no hit", 16);
    rayText.setFillColor(rayColor);
    rayText.setPosition({700.f, 8.f});
    target.draw(rayText);
}

void RayLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    for (const hitbox::Hit& hit : lastHits) // where each hit touched, and its normal
        debug.arrow(hit.point, hit.point + hit.normal * 24.f, hitbox::DebugRenderer::normalColor);
    // The swept area of the next quarter second, and the player's velocity.
    debug.objectBox(player, !lastHits.empty());
    if (ray.boxIndex >= 0)
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

using RaySnapshot = hitbox::WholeLevelCopy<RayLevel>; // Level.h: a copy of the whole level

std::unique_ptr<hitbox::LevelState> RayLevel::saveState() const
{
    const std::size_t held = sizeof(RaySnapshot) + solids.size() * sizeof(hitbox::Box) +
                             pillars.size() * sizeof(hitbox::Circle) +
                             lastHits.size() * sizeof(hitbox::Hit) +
                             trail.size() * sizeof(sf::Vector2f);
    return std::make_unique<RaySnapshot>(*this, held);
}

void RayLevel::restoreState(const hitbox::LevelState& state)
{
    *this = static_cast<const RaySnapshot&>(state).level;
}
