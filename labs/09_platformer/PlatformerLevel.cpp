#include "PlatformerLevel.h"

#include "Platforms.h"

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
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>

namespace
{
const sf::Color tileColor{70, 96, 150};
const sf::Color tileEdgeColor{100, 130, 190};
const sf::Color playerColor{240, 180, 70};
const sf::Color groundedColor{90, 230, 120};
const sf::Color plankColor{190, 150, 90};       // one-way platforms
const sf::Color flagColor{230, 90, 60};         // a checkpoint not entered yet
const sf::Color reachedFlagColor{90, 230, 120}; // the checkpoint the player restarts from
const float plankThickness = 8.f;
const float helpBarHeight = 24.f; // the App's help line sits under the map, not on it
const float hudTextSize = 18.f;

// The smallest box holding both boxes.
hitbox::Box unionOf(const hitbox::Box& a, const hitbox::Box& b)
{
    const float left = std::min(a.left, b.left);
    const float top = std::min(a.top, b.top);
    const float right = std::max(hitbox::rightOf(a), hitbox::rightOf(b));
    const float bottom = std::max(hitbox::bottomOf(a), hitbox::bottomOf(b));
    return {left, top, right - left, bottom - top};
}

void addQuad(sf::VertexArray& quads, const hitbox::Box& box, sf::Color color)
{
    const hitbox::Vec2 corners[4] = {{box.left, box.top},
                                     {box.left + box.width, box.top},
                                     {box.left + box.width, box.top + box.height},
                                     {box.left, box.top + box.height}};
    for (int index : {0, 1, 2, 0, 2, 3})
        quads.append(sf::Vertex{hitbox::toSfml(corners[index]), color});
}

// A corner at the bottom of the player's box (not the middle of the bottom: the foot).
bool isBottomCorner(const CollisionPoint& point)
{
    return point.side.y > 0.f && point.side.x != 0.f;
}

// The smallest box holding both boxes, and `extraBelow` pixels more at the bottom.
hitbox::Box reachOf(const hitbox::Box& a, const hitbox::Box& b, float extraBelow)
{
    hitbox::Box reach = unionOf(a, b);
    reach.height += extraBelow;
    return reach;
}
} // namespace

// [slide:platformer-collision-points]
// The collision points: A bottom, B top, C left, D right, then the four corners, checked in
// this order. With a player at most 1.5 tiles tall no tile can slip between two points.
const std::array<CollisionPoint, 8> PlatformerLevel::collisionPoints = {{
    {"bottom", {0.f, 1.f}},
    {"top", {0.f, -1.f}},
    {"left", {-1.f, 0.f}},
    {"right", {1.f, 0.f}},
    {"left top", {-1.f, -1.f}},
    {"right top", {1.f, -1.f}},
    {"left bottom", {-1.f, 1.f}},
    {"right bottom", {1.f, 1.f}},
}};

hitbox::Vec2 PlatformerLevel::pointOn(const hitbox::Box& box, const CollisionPoint& point)
{
    return {box.left + box.width * (point.side.x + 1.f) / 2.f,
            box.top + box.height * (point.side.y + 1.f) / 2.f};
}
// [/slide]

// [slide:platformer-least-penetration]
hitbox::Contact PlatformerLevel::pushOut(const CollisionPoint& point, hitbox::Vec2 where,
                                         const hitbox::Box& tile)
{
    // How far the point went into the tile, measured from the tile edge on the point's side
    // of the player (a left point came in through the tile's right edge, and so on).
    const float depthX = point.side.x < 0.f ? hitbox::rightOf(tile) - where.x : where.x - tile.left;
    const float depthY = point.side.y < 0.f ? hitbox::bottomOf(tile) - where.y : where.y - tile.top;
    const float edgeX = point.side.x < 0.f ? hitbox::rightOf(tile) : tile.left;
    const float edgeY = point.side.y < 0.f ? hitbox::bottomOf(tile) : tile.top;
    const hitbox::Contact pushX{true, {-point.side.x, 0.f}, depthX, {edgeX, where.y}};
    const hitbox::Contact pushY{true, {0.f, -point.side.y}, depthY, {where.x, edgeY}};

    if (point.side.y == 0.f)
        return pushX; // a side point: straight back out through its own side
    if (point.side.x == 0.f)
        return pushY;

    // BEGIN TASK 2: push a corner out along the axis of least penetration
    // A corner cannot tell whether it came in from above or from the side. The shallower
    // way out is nearly always the way it came in. Ties: the x axis.
    return depthY < depthX ? pushY : pushX;
    // STARTER TASK 2
    // return hitbox::Contact{}; // for now a corner inside a tile is ignored
    // END TASK 2
}
// [/slide]

hitbox::Slope PlatformerLevel::slopeOf(Tile tile, const hitbox::Box& tileBox)
{
    const float bottom = hitbox::bottomOf(tileBox);
    const float right = hitbox::rightOf(tileBox);
    if (tile == Tile::SlopeUp)
        return {{tileBox.left, bottom}, {right, tileBox.top}};
    return {{tileBox.left, tileBox.top}, {right, bottom}};
}

PlatformerLevel::PlatformerLevel(TileMap levelMap) : map(std::move(levelMap))
{
    for (int row = 0; row < map.getRows(); ++row)
        for (int column = 0; column < map.getColumns(); ++column)
        {
            const hitbox::Vec2 tile{map.tileBox(column, row).left, map.tileBox(column, row).top};
            const bool start = tile == map.getPlayerStart();
            if ((start || map.tileAt(column, row) == Tile::Checkpoint) && isUnderACeiling(tile) &&
                map.isSolid(column, row + 1))
                throw std::invalid_argument(
                    std::string(start ? "the player start 'P'" : "the checkpoint 'C'") +
                    " (column " + std::to_string(column + 1) + ", row " + std::to_string(row + 1) +
                    ") has solid tiles above and below it; the player is taller than one tile, "
                    "so leave the tile above or below " +
                    (start ? "'P'" : "'C'") + " empty");
        }
    respawnTile = map.getPlayerStart();
    respawn();
    for (int row = 0; row < map.getRows(); ++row)
        for (int column = 0; column < map.getColumns(); ++column)
        {
            const Tile tile = map.tileAt(column, row);
            const hitbox::Box box = map.tileBox(column, row);
            if (tile == Tile::Solid)
            {
                addQuad(tileQuads, box, tileEdgeColor);
                addQuad(tileQuads,
                        {box.left + 2.f, box.top + 2.f, box.width - 4.f, box.height - 4.f},
                        tileColor);
            }
            else if (tile == Tile::OneWay) // a plank: only its top is solid
                addQuad(tileQuads, {box.left, box.top, box.width, plankThickness}, plankColor);
            else if (tile == Tile::SlopeUp || tile == Tile::SlopeDown)
            {
                // The solid triangle under the surface.
                const hitbox::Slope slope = slopeOf(tile, box);
                const hitbox::Vec2 corner{tile == Tile::SlopeUp ? hitbox::rightOf(box) : box.left,
                                          hitbox::bottomOf(box)};
                for (const hitbox::Vec2 point : {slope.left, slope.right, corner})
                    tileQuads.append(sf::Vertex{hitbox::toSfml(point), tileColor});
            }
        }
}

void PlatformerLevel::handleInput(const hitbox::Input& input, float)
{
    holdingLeft = input.isKeyDown(sf::Keyboard::Key::A) || input.isKeyDown(sf::Keyboard::Key::Left);
    holdingRight =
        input.isKeyDown(sf::Keyboard::Key::D) || input.isKeyDown(sf::Keyboard::Key::Right);
    // A press is kept until a step uses it, whatever the frame rate.
    if (input.isPressed(sf::Keyboard::Key::Space) || input.isPressed(sf::Keyboard::Key::W) ||
        input.isPressed(sf::Keyboard::Key::Up))
        jumpPressed = true;
    if (input.isPressed(sf::Keyboard::Key::S) || input.isPressed(sf::Keyboard::Key::Down))
        divePressed = true;
    if (input.isPressed(sf::Keyboard::Key::C))
        speedCapOn = !speedCapOn;
    if (input.isPressed(sf::Keyboard::Key::X))
        speculative = !speculative;
    if (input.isPressed(sf::Keyboard::Key::R))
        respawn();
}

// [slide:platformer-fixed-step]
// Frame-rate independence: whatever dt the caller passes (a 30 Hz laptop, a 240 Hz
// monitor), the level simulates whole steps of exactly hitbox::stepSeconds, so the same
// key presses give the same jump everywhere. hitbox::FixedStep keeps the leftover time for
// the next call and, after a long stall, skips time rather than freezing to catch up.
void PlatformerLevel::update(float dt)
{
    const int steps = fixedStep.advance(dt);
    for (int i = 0; i < steps; ++i)
        step();
}
// [/slide]

void PlatformerLevel::step()
{
    PlayerControls controls{holdingLeft, holdingRight, jumpPressed, divePressed};
    if (demo) // run right, jump every half second
        controls = {false, true, stepCount % 60 == 0, false};
    jumpPressed = false;
    divePressed = false;
    if (steering)
        player.steer(controls, grounded, speedCapOn, hitbox::stepSeconds);

    const hitbox::Box before = player.getBox();
    contacts.clear();
    pushingTiles.clear();
    pointWasInside.fill(false);
    wasGrounded = grounded;
    grounded = false;
    onSlope = false;
    if (speculative)
        moveWithSpeculativeContacts(before);
    else
        moveThenResolve(before);
    checkCheckpoints(before);
    ++stepCount;

    // Fell out of the bottom of the map (through a hole, or through a floor too fast).
    if (player.getPosition().y > map.getSizeInPixels().y + 4.f * TileMap::tileSize)
    {
        ++fallsOutOfWorld;
        respawn();
    }
}

void PlatformerLevel::moveThenResolve(const hitbox::Box& before)
{
    player.setPosition(player.getPosition() + plannedMove(before));
    resolvePenetration(before);
}

hitbox::Vec2 PlatformerLevel::plannedMove(const hitbox::Box& before)
{
    hitbox::Vec2 move = player.getVelocity() * hitbox::stepSeconds;
    const hitbox::Box after{before.left + move.x, before.top + move.y, before.width, before.height};
    const TileRegion region = tilesToTest(reachOf(before, after, 0.f));
    bool landed = false;
    for (int row = region.firstRow; row <= region.lastRow; ++row)
        for (int column = region.firstColumn; column <= region.lastColumn; ++column)
        {
            if (map.tileAt(column, row) != Tile::OneWay)
                continue;
            const hitbox::OneWayStop stop = landOnOneWay(before, move, map.tileBox(column, row));
            if (!stop.blocked)
                continue;
            move = stop.move; // the highest platform under the fall wins: the move only shrinks
            landed = true;
            pushingTiles.push_back(map.tileBox(column, row));
        }
    if (landed) // a floor under the feet: grounded, and the fall stops (depth 0: no push)
        applyPush({true,
                   {0.f, -1.f},
                   0.f,
                   {hitbox::centerOf(after).x, hitbox::bottomOf(before) + move.y}});
    return move;
}

void PlatformerLevel::standOnSlopes(const hitbox::Box& before)
{
    // Pulled down onto a slope only while walking (grounded the step before): a falling
    // player lands when its foot reaches the surface. The reach looks that far below too.
    const float snap = wasGrounded ? slopeSnapDistance : 0.f;
    const TileRegion region = tilesToTest(reachOf(before, player.getBox(), snap));
    for (int row = region.firstRow; row <= region.lastRow; ++row)
        for (int column = region.firstColumn; column <= region.lastColumn; ++column)
        {
            const Tile tile = map.tileAt(column, row);
            if (tile != Tile::SlopeUp && tile != Tile::SlopeDown)
                continue;
            const hitbox::Box tileBox = map.tileBox(column, row);
            const hitbox::SlopeFoot foot =
                footOnSlope(player.getBox(), player.getVelocity().y, slopeOf(tile, tileBox), snap);
            if (!foot.grounded)
                continue;
            player.setPosition(player.getPosition() + hitbox::Vec2(0.f, foot.moveY));
            onSlope = true;
            pushingTiles.push_back(tileBox);
            const hitbox::Box box = player.getBox();
            applyPush({true, {0.f, -1.f}, 0.f, {hitbox::centerOf(box).x, hitbox::bottomOf(box)}});
            return; // one slope holds the foot
        }
}

void PlatformerLevel::checkCheckpoints(const hitbox::Box& before)
{
    const TileRegion region = tilesToTest(reachOf(before, player.getBox(), 0.f));
    for (int row = region.firstRow; row <= region.lastRow; ++row)
        for (int column = region.firstColumn; column <= region.lastColumn; ++column)
        {
            if (map.tileAt(column, row) != Tile::Checkpoint)
                continue;
            const hitbox::Box zone = map.tileBox(column, row);
            // BEGIN TASK 7: a checkpoint is a trigger: it reports the player entering it
            // Entering: overlapping the zone now, but not when the step began (touching its
            // edge is neither: the edge rule). A trigger reports and never pushes: the player's
            // position and velocity are left as the move made them.
            if (hitbox::boxVsBox(player.getBox(), zone) && !hitbox::boxVsBox(before, zone))
            {
                ++checkpointEntries;
                respawnTile = {zone.left, zone.top};
            }
            // STARTER TASK 7
            // (void)before;
            // (void)zone; // for now a checkpoint never notices the player
            // END TASK 7
        }
}

TileRegion PlatformerLevel::tilesToTest(const hitbox::Box& box) const
{
    if (wholeMap)
        return {0, map.getColumns() - 1, 0, map.getRows() - 1};
    return map.tilesUnder(box);
}

std::vector<hitbox::Box> PlatformerLevel::solidTilesIn(const TileRegion& region) const
{
    std::vector<hitbox::Box> solids;
    for (int row = region.firstRow; row <= region.lastRow; ++row)
        for (int column = region.firstColumn; column <= region.lastColumn; ++column)
            if (map.isSolid(column, row))
                solids.push_back(map.tileBox(column, row));
    return solids;
}

void PlatformerLevel::resolvePenetration(const hitbox::Box& before)
{
    // Over a slope the foot decides where the player stands; the bottom corners may hang
    // into the block at the slope's top, and must not push the player back off the slope.
    const bool skipBottomCorners = isFootOverASlope();
    resolveCollisionPoints(before, skipBottomCorners);
    // After the points: a foot pushed back out of the floor at a slope's low end is on it.
    standOnSlopes(before);
}

bool PlatformerLevel::isFootOverASlope() const
{
    const hitbox::Box box = player.getBox();
    // A tile index clipped to just outside the map before it becomes an int: far away, an int
    // would overflow.
    auto index = [](float pixels, int count)
    {
        return static_cast<int>(std::clamp(std::floor(pixels / TileMap::tileSize), -2.f,
                                           static_cast<float>(count) + 1.f));
    };
    const int column = index(hitbox::centerOf(box).x, map.getColumns());
    const int row = index(hitbox::bottomOf(box), map.getRows());
    for (const int under : {row, row - 1}) // the tile the foot is in, or the one above it
    {
        const Tile tile = map.tileAt(column, under);
        if (tile == Tile::SlopeUp || tile == Tile::SlopeDown)
            return true;
    }
    return false;
}

void PlatformerLevel::resolveCollisionPoints(const hitbox::Box& before, bool skipBottomCorners)
{
    // [slide:platformer-resolve]
    sweptBounds = before;
    for (passesUsed = 1; passesUsed <= maxResolvePasses; ++passesUsed)
    {
        // Broad phase: only the tiles under where the player was and where it is now.
        sweptBounds = unionOf(sweptBounds, player.getBox());
        testedRegion = tilesToTest(sweptBounds);
        bool pushed = false;
        for (std::size_t index = 0; index < collisionPoints.size(); ++index)
            for (const hitbox::Box& tile : solidTilesIn(testedRegion))
            {
                if (skipBottomCorners && isBottomCorner(collisionPoints[index]))
                    continue;
                const hitbox::Vec2 where = pointOn(player.getBox(), collisionPoints[index]);
                if (!hitbox::pointInBox(where, tile))
                    continue;
                pointWasInside[index] = true;
                const hitbox::Contact push = pushOut(collisionPoints[index], where, tile);
                if (push.hit)
                {
                    applyPush(push);
                    pushingTiles.push_back(tile);
                    pushed = true;
                }
            }
        if (!pushed)
            return; // nothing is inside any more: done for this step
    }
    // [/slide]
    passesUsed = maxResolvePasses;
}

// [slide:platformer-grounded]
void PlatformerLevel::applyPush(const hitbox::Contact& push)
{
    player.setPosition(player.getPosition() + push.normal * push.depth);
    // Stop the part of the velocity that goes into the surface (so gravity does not build up
    // while standing), and keep the part along it (so the player slides along walls). The part
    // along the normal is negative when the player moves into the surface.
    hitbox::Vec2 velocity = player.getVelocity();
    const float alongNormal = velocity.x * push.normal.x + velocity.y * push.normal.y;
    if (alongNormal < 0.f)
        velocity -= push.normal * alongNormal;
    player.setVelocity(velocity);
    // Pushed up = something under the feet: a floor. This is the only way to be grounded
    // (the bottom point, or a bottom corner resolved along y).
    if (push.normal.y < 0.f)
        grounded = true;
    contacts.push_back(push);
}
// [/slide]

hitbox::Hit PlatformerLevel::firstHitAlong(const hitbox::Box& box, hitbox::Vec2 move) const
{
    const hitbox::Box moved{box.left + move.x, box.top + move.y, box.width, box.height};
    hitbox::Hit first;
    for (const hitbox::Box& tile : solidTilesIn(tilesToTest(unionOf(box, moved))))
    {
        const hitbox::Hit hit = hitbox::sweepBoxVsBox(box, move, tile);
        if (hit && !hit.startedInside && hit.time < first.time)
            first = hit;
    }
    return first;
}

// [slide:platformer-speculative]
// Speculative contacts (Katy Coe, "2D Platform Games Part 1: Collision Detection for Dummies"):
// instead of moving and then repairing, sweep the player's box along its move and stop it where it
// would first touch a tile. The rest of the move slides along the surface. A fast player can no
// longer pass through a thin floor.
void PlatformerLevel::moveWithSpeculativeContacts(const hitbox::Box& before)
{
    hitbox::Vec2 move = plannedMove(before);
    for (int pass = 0; pass < maxResolvePasses && (move.x != 0.f || move.y != 0.f); ++pass)
    {
        const hitbox::Hit first = firstHitAlong(player.getBox(), move);
        if (!first.hit)
        {
            player.setPosition(player.getPosition() + move);
            break;
        }
        player.setPosition(player.getPosition() + move * first.time); // just touching
        applyPush({true, first.normal, 0.f, first.point});
        // What is left of the move, minus the part that would go into the surface (the part
        // along the normal, when it is negative).
        move *= 1.f - first.time;
        const float alongNormal = move.x * first.normal.x + move.y * first.normal.y;
        if (alongNormal < 0.f)
            move -= first.normal * alongNormal;
    }
    resolvePenetration(before); // anything that started inside is pushed out as usual
}
// [/slide]

void PlatformerLevel::placePlayer(hitbox::Vec2 topLeft)
{
    player = Player(topLeft);
    grounded = false;
}

void PlatformerLevel::respawn()
{
    // Stand on the bottom of the 'P' tile (or of the last checkpoint), in the middle of it.
    // The player is taller than a tile: under a solid tile it starts with its head at the top
    // of the tile instead and falls, never with its head inside the ceiling (the constructor
    // refuses a one-tile gap).
    const hitbox::Vec2 start = respawnTile;
    const float top =
        isUnderACeiling(start) ? start.y : start.y + TileMap::tileSize - Player::height;
    placePlayer({start.x + (TileMap::tileSize - Player::width) / 2.f, top});
}

bool PlatformerLevel::isUnderACeiling(hitbox::Vec2 tileTopLeft) const
{
    return map.isSolid(static_cast<int>(tileTopLeft.x / TileMap::tileSize),
                       static_cast<int>(tileTopLeft.y / TileMap::tileSize) - 1);
}

void PlatformerLevel::render(sf::RenderTarget& target) const
{
    target.draw(tileQuads);
    // The checkpoints: a flag on a pole, green on the one the player restarts from.
    for (int row = 0; row < map.getRows(); ++row)
        for (int column = 0; column < map.getColumns(); ++column)
            if (map.tileAt(column, row) == Tile::Checkpoint)
            {
                const hitbox::Box box = map.tileBox(column, row);
                sf::RectangleShape pole({4.f, box.height - 6.f});
                pole.setPosition(hitbox::toSfml({box.left + 10.f, box.top + 6.f}));
                pole.setFillColor(sf::Color(220, 220, 220));
                target.draw(pole);
                const bool current = respawnTile == hitbox::Vec2(box.left, box.top);
                sf::RectangleShape flag({22.f, 14.f});
                flag.setPosition(hitbox::toSfml({box.left + 14.f, box.top + 6.f}));
                flag.setFillColor(current ? reachedFlagColor : flagColor);
                target.draw(flag);
            }

    sf::RectangleShape body({Player::width, Player::height});
    body.setPosition(hitbox::toSfml(player.getPosition()));
    body.setFillColor(playerColor);
    target.draw(body);
    // Eyes on the side the player runs towards, so its direction is easy to follow.
    sf::RectangleShape eye({5.f, 9.f});
    eye.setFillColor(sf::Color(40, 30, 20));
    const float facing = player.getVelocity().x < 0.f ? 3.f : Player::width - 9.f;
    eye.setPosition(hitbox::toSfml(player.getPosition() + hitbox::Vec2(facing, 12.f)));
    target.draw(eye);

    std::ostringstream hud;
    hud << (grounded ? "GROUNDED" : "in the air")
        << "    speed cap [C]: " << (speedCapOn ? "on" : "OFF")
        << "    speculative contacts [X]: " << (speculative ? "ON" : "off")
        << "    tiles tested: " << testedRegion.tileCount() << "    fell out: " << fallsOutOfWorld
        << "    checkpoints: " << checkpointEntries;
    // On a dark strip over the top row, so it never hides the player.
    sf::RectangleShape strip({map.getSizeInPixels().x, hudTextSize + 14.f});
    strip.setFillColor(sf::Color(0, 0, 0, 170));
    target.draw(strip);
    sf::Text text = hitbox::makeText(font.get(), hud.str(), static_cast<unsigned>(hudTextSize));
    text.setPosition({10.f, 5.f});
    text.setFillColor(grounded ? groundedColor : sf::Color::White);
    target.draw(text);
}

void PlatformerLevel::renderDebug(hitbox::DebugRenderer& debug) const
{
    using hitbox::DebugRenderer;
    // The tiles the broad phase handed to the collision points, and the swept bounds.
    for (int row = testedRegion.firstRow; row <= testedRegion.lastRow; ++row)
        for (int column = testedRegion.firstColumn; column <= testedRegion.lastColumn; ++column)
            debug.box(map.tileBox(column, row), map.isSolid(column, row)
                                                    ? DebugRenderer::freeColor
                                                    : DebugRenderer::hintColor);
    for (const hitbox::Box& tile : pushingTiles)
        debug.box(tile, hitbox::DebugState::Overlapping);
    debug.box(sweptBounds, DebugRenderer::hintColor);

    const hitbox::Box box = player.getBox();
    debug.box(box, contacts.empty() ? hitbox::DebugState::Free : hitbox::DebugState::Overlapping);
    debug.arrow(hitbox::centerOf(box), hitbox::centerOf(box) + player.getVelocity() * 0.25f,
                DebugRenderer::velocityColor);
    // The collision points: vermillion if the point was inside a solid tile this step. Small
    // crosses: the points are half the player's width apart, and bigger ones run into each other.
    for (std::size_t index = 0; index < collisionPoints.size(); ++index)
        debug.cross(pointOn(box, collisionPoints[index]), 4.f,
                    pointWasInside[index] ? DebugRenderer::overlappingColor
                                          : DebugRenderer::freeColor);
    for (const hitbox::Contact& contact : contacts)
        debug.contact(contact);
    if (grounded) // a bar under the feet: "standing on something"
        debug.line({box.left - 4.f, hitbox::bottomOf(box) + 4.f},
                   {hitbox::rightOf(box) + 4.f, hitbox::bottomOf(box) + 4.f}, groundedColor);
}

sf::Vector2f PlatformerLevel::getWorldSize() const
{
    return hitbox::toSfml(map.getSizeInPixels() + hitbox::Vec2(0.f, helpBarHeight));
}

std::string PlatformerLevel::getHelpText() const
{
    return "A/D run  Space jump  S dive  C speed cap  X speculative  R back to the checkpoint";
}

std::string PlatformerLevel::describeState() const
{
    std::ostringstream out;
    out << "player at (" << player.getPosition().x << ", " << player.getPosition().y << ")"
        << (grounded ? " grounded" : " in the air") << ", fell out " << fallsOutOfWorld
        << " times, last step tested " << testedRegion.tileCount() << " tiles, "
        << checkpointEntries << " checkpoint entries";
    return out.str();
}
