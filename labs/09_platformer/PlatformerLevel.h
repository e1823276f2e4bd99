// PlatformerLevel.h - Lab 9: a player running and jumping through a tile level.
//
// Each fixed step:
//   1. the controls change the velocity (Player::steer: run, brake, gravity, jump, speed cap);
//   2. the player moves by velocity * step;
//   3. broad phase: only the tiles under the SWEPT BOUNDS (the box covering where the player
//      was and where it is now) are looked at, never the whole map;
//   4. eight collision points around the player are tested against those tiles in a fixed
//      order; a point inside a solid tile pushes the player out (corners along the axis of
//      least penetration); a push upwards means the feet are on a floor: grounded.
// Key X switches to speculative contacts: the move is cut short where the player would
// first touch a tile, so it stops even when it is too fast for step 4 (bullet through paper).
// The tiles that are not square blocks have their own rules: a one-way platform cuts the move
// before step 2 (task 5), a slope holds the player's foot on its surface before step 4
// (task 6), and a checkpoint is a trigger: after the step it reports the player entering it
// and never pushes (task 7).
#pragma once

#include "Player.h"
#include "TileMap.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Assets.h"
#include "hitbox/app/FixedStep.h"
#include "hitbox/app/Level.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Slope.h"
#include "hitbox/geometry/Sweep.h"

#include <SFML/Graphics/VertexArray.hpp>

#include <array>
#include <string>
#include <vector>

// A point on the player's box that is tested against the tiles (A, B, C, D and
// the corners). `side` says which sides of the box it lies on: x -1 left, +1 right, 0 middle;
// y -1 top, +1 bottom, 0 middle. A point is pushed out towards the inside of the box.
struct CollisionPoint
{
    const char* name;
    hitbox::Vec2 side;
};

class PlatformerLevel : public hitbox::Level
{
public:
    // The collision points in the order they are checked: bottom, top, left,
    // right, then the corners. The sides first, so that a corner is only used when no side
    // point already settled the collision.
    static const std::array<CollisionPoint, 8> collisionPoints;
    // Resolving one point can push another into a tile: repeat up to this many times per
    // step, stopping early when nothing is inside (iterative resolution, as in
    // Katy Coe, "2D Platform Games Part 1: Collision Detection for Dummies").
    static constexpr int maxResolvePasses = 3;
    // How far above a slope the foot of a player who stood on the ground the step before is
    // pulled down onto it (task 6): a quarter tile, more than the 3.5 px a 45-degree slope
    // drops under a full-speed run in one step, so walking down a slope never leaves it. A
    // falling player is not pulled: it lands when its foot reaches the surface.
    static constexpr float slopeSnapDistance = TileMap::tileSize / 4.f;

    // The surface of a slope tile ('/' or '\'), from its left edge to its right edge.
    [[nodiscard]] static hitbox::Slope slopeOf(Tile tile, const hitbox::Box& tileBox);

    // Throws std::invalid_argument when 'P' or a checkpoint 'C' has solid tiles both above and
    // below it: the player, taller than a tile, could not start there without a tile inside it.
    explicit PlatformerLevel(TileMap map);

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    sf::Vector2f getWorldSize() const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // Where a collision point lies on a box, in world pixels.
    static hitbox::Vec2 pointOn(const hitbox::Box& box, const CollisionPoint& point);
    // The push that takes `point` (at `where`, inside `tile`) out of the tile: side points
    // straight back through their own side, corners along the axis of least penetration.
    static hitbox::Contact pushOut(const CollisionPoint& point, hitbox::Vec2 where,
                                   const hitbox::Box& tile);

    // Put the player somewhere (top-left corner of its box), standing still. For tests and
    // for restarting; the next step starts from there.
    void placePlayer(hitbox::Vec2 topLeft);
    // Set the player's velocity (pixels per second) for the next step. For tests.
    void setPlayerVelocity(hitbox::Vec2 velocity) { player.setVelocity(velocity); }
    // Steer the player from the keys (the default). Off, for tests: each step moves the player
    // by the velocity setPlayerVelocity gave (less what a push stopped), with no gravity, jump
    // or speed cap, so the tests of tasks 5-7 cost nothing when task 1 or 4 is wrong.
    void setSteering(bool on) { steering = on; }

    const Player& getPlayer() const { return player; }
    const TileMap& getMap() const { return map; }
    bool isGrounded() const { return grounded; }
    bool isSpeedCapOn() const { return speedCapOn; }
    void setSpeedCap(bool on) { speedCapOn = on; }
    // Demo mode (for lectures and screenshots): the player runs right and jumps by itself.
    void setDemo(bool on) { demo = on; }
    bool usesSpeculativeContacts() const { return speculative; }
    void setSpeculativeContacts(bool on) { speculative = on; }
    // Test every tile of the map instead of only those under the swept bounds (task 3): the
    // same answers, more work. The tests of the other tasks switch it on, so a mistake in
    // task 3 costs task 3 alone.
    bool searchesWholeMap() const { return wholeMap; }
    void setWholeMapSearch(bool on) { wholeMap = on; }
    // The tiles looked at in the last step (the swept-bounds region), solid or not.
    const TileRegion& getTestedRegion() const { return testedRegion; }
    const hitbox::Box& getSweptBounds() const { return sweptBounds; }
    // The pushes made in the last step, in the order they were made.
    const std::vector<hitbox::Contact>& getContacts() const { return contacts; }
    int getResolvePassesLastStep() const { return passesUsed; }
    long long getStepCount() const { return stepCount; }
    int getFallsOutOfWorld() const { return fallsOutOfWorld; }
    // True when the player's foot stood on a slope in the last step (task 6).
    bool isOnSlope() const { return onSlope; }
    // Task 7: how many times the player has entered a checkpoint (each entry once), and the
    // top-left corner of the tile it starts from after a fall or R: the last checkpoint
    // entered, or 'P'.
    int getCheckpointEntries() const { return checkpointEntries; }
    hitbox::Vec2 getRespawnTile() const { return respawnTile; }

private:
    void step();
    void moveThenResolve(const hitbox::Box& before);
    void moveWithSpeculativeContacts(const hitbox::Box& before);
    void resolvePenetration(const hitbox::Box& before);
    void applyPush(const hitbox::Contact& push);
    // This step's move: velocity * step, cut by the one-way platforms under it (task 5).
    hitbox::Vec2 plannedMove(const hitbox::Box& before);
    // The collision points against the solid tiles, a few passes (and slopes after them).
    void resolveCollisionPoints(const hitbox::Box& before, bool skipBottomCorners);
    // True when the middle of the player's bottom is in a slope tile or just above one.
    bool isFootOverASlope() const;
    // Task 6 at work: the foot put on the slope under it, if any.
    void standOnSlopes(const hitbox::Box& before);
    // Task 7: the checkpoints the player entered this step.
    void checkCheckpoints(const hitbox::Box& before);
    // The tiles under a box (task 3's tilesUnder), or every tile with setWholeMapSearch.
    TileRegion tilesToTest(const hitbox::Box& box) const;
    // The boxes of the solid tiles in a region.
    std::vector<hitbox::Box> solidTilesIn(const TileRegion& region) const;
    // The earliest tile a box moving by `move` would run into (sweepBoxVsBox).
    hitbox::Hit firstHitAlong(const hitbox::Box& box, hitbox::Vec2 move) const;
    void respawn();
    // True when the tile above this one is solid: the player (taller than a tile) starts lower.
    bool isUnderACeiling(hitbox::Vec2 tileTopLeft) const;

    TileMap map;
    Player player;
    sf::VertexArray tileQuads{sf::PrimitiveType::Triangles}; // built once: the tiles never change
    hitbox::LazyFont font; // read by the first render(): tests need no font file

    // Controls: held keys, and presses kept until the next step uses them.
    bool holdingLeft = false;
    bool holdingRight = false;
    bool jumpPressed = false;
    bool divePressed = false;

    bool speedCapOn = true;
    bool speculative = false;
    bool wholeMap = false;
    bool demo = false;
    bool steering = true;
    hitbox::FixedStep fixedStep{hitbox::stepSeconds}; // frame time -> whole steps
    long long stepCount = 0;
    int fallsOutOfWorld = 0;

    // What the last step found (the debug view and the tests read these).
    bool grounded = false;
    bool wasGrounded = false; // grounded at the end of the step before this one
    bool onSlope = false;
    int checkpointEntries = 0;
    hitbox::Vec2 respawnTile;
    TileRegion testedRegion;
    hitbox::Box sweptBounds;
    std::vector<hitbox::Contact> contacts;
    std::vector<hitbox::Box> pushingTiles;
    std::array<bool, 8> pointWasInside{};
    int passesUsed = 0;
};
