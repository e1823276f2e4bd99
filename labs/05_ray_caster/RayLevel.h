// RayLevel.h - a ray from the player to the mouse, and a player that slides along walls.
//
// Part 1: cast a ray (a segment) from the player's centre to the mouse against every box and
// keep the NEAREST hit: that is what a gun, a line of sight or a laser needs.
// Part 2: move the player with hitbox::moveBoxAndSlide, which sweeps its box so it stops at
// walls at any speed and slides along them. Its floor is made of separate tiles: sliding over
// the seams only works because the contacts are handled in TIME ORDER (T turns that off).
// Part 3: notice when a step snags. (The ladder of javidx9's video "Arbitrary Rectangle
// Collision Detection & Resolution", OneLoneCoder, 2020.)
#pragma once

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/objects/GameObject.h"

#include <cstddef>
#include <memory>
#include <vector>

// The answer of castRay: the ray runs from `start` to `end`, and `end` is the hit point
// when it hit something.
struct RayHit
{
    bool hit = false;
    hitbox::Vec2 start;
    hitbox::Vec2 end;
    hitbox::Vec2 normal;  // the surface normal at the hit, unit length when hit
    float time = 1.f;     // how far along the ray: 0 at the start, 1 at the mouse
    int boxIndex = -1;    // which of getSolids() it hit, -1 when none
    int pillarIndex = -1; // which of getPillars() it hit (task 4), -1 when none
};

// Task 3: true when a step that wanted to move by `wanted` moved by less than a tenth of
// that (`moved`): snagged on a seam or pressed into a corner. A zero `wanted` is never stuck.
bool isSnagged(sf::Vector2f wanted, sf::Vector2f moved);

class RayLevel : public hitbox::Level
{
public:
    // The lab's field of boxes and tiles, the player sliding down-left along the floor.
    RayLevel();
    // Any set of solid boxes and a player box starting at `playerStart` (tests use this).
    RayLevel(std::vector<hitbox::Box> solids, sf::Vector2f playerStart);

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;
    // The window's rewind (hitbox::RewindLevel): a copy of the whole level, which is all
    // values, so a field added to it is rewound too. Without it the rewind re-simulates from
    // the start, and a step of this lab is slow enough for that to show.
    std::unique_ptr<hitbox::LevelState> saveState() const override;
    void restoreState(const hitbox::LevelState& state) override;

    // Task 1: the nearest solid the segment from `from` to `to` hits.
    RayHit castRay(hitbox::Vec2 from, hitbox::Vec2 to) const;

    // true: handle the contacts of a step in time order (the fix); false: in list order.
    void setTimeOrder(bool on);
    bool usesTimeOrder() const;
    // Where the player wants to go: each axis -1, 0 or 1 (like holding the arrow keys).
    void setMoveDirection(sf::Vector2f direction);

    const hitbox::GameObject& getPlayer() const;
    const std::vector<hitbox::Box>& getSolids() const;
    // The round pillars (task 4): only the lab's own field has them.
    const std::vector<hitbox::Circle>& getPillars() const;
    const RayHit& getRay() const;
    // The hits of the player's last step, in the order moveBoxAndSlide resolved them.
    const std::vector<hitbox::Hit>& getLastHits() const;
    // The player wanted to move in the last step but hardly moved (snagged or cornered).
    bool isStuck() const;

private:
    // `boxHit` (castRay's answer for the ray to `to`), or a pillar the ray meets sooner
    // (rayCircleTime, task 4).
    RayHit stopAtPillars(RayHit boxHit, hitbox::Vec2 to) const;
    // Move the player by velocity * dt, sliding along what it runs into (task 2).
    void movePlayer(sf::Vector2f velocity, float dt);

    std::vector<hitbox::Box> solids;
    std::vector<hitbox::Circle> pillars;
    hitbox::GameObject player;
    sf::Vector2f moveDirection{-1.f, 1.f}; // the demo: down-left along the tiled floor
    bool keyboardControl = false;          // a movement key has been pressed
    bool timeOrder = true;
    sf::Vector2f mouse;
    sf::Vector2f lastMouseReading;
    RayHit ray;
    std::vector<hitbox::Hit> lastHits;
    bool stuck = false;              // wanted to move this step but hardly moved
    std::vector<sf::Vector2f> trail; // where the player has been, for the picture
    hitbox::LazyFont font;           // read by the first render(): tests need no font file
};
