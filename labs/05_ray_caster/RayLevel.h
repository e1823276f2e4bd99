// RayLevel.h - a ray from the player to the mouse, and a player that slides along walls.
//
// Part 1: cast a ray (a segment) from the player's centre to the mouse against every box and
// keep the NEAREST hit: that is what a gun, a line of sight or a laser needs.
// Part 2: move the player with a swept box, so it stops at walls at any speed, and slide
// along them instead of sticking. Part 3: the floor is made of separate tiles, and sliding
// over the seams between them only works if the contacts are handled in TIME ORDER (seed 004).
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/objects/GameObject.h"

#include <SFML/Graphics/Font.hpp>

#include <cstddef>
#include <vector>

// The answer of castRay: the ray runs from `start` to `end`, and `end` is the hit point
// when it hit something.
struct RayHit
{
    bool hit = false;
    hitbox::Vec2 start;
    hitbox::Vec2 end;
    hitbox::Vec2 normal; // the surface normal at the hit, unit length when hit
    float time = 1.f;    // how far along the ray: 0 at the start, 1 at the mouse
    int boxIndex = -1;   // which of getSolids() it hit, -1 when none
};

// One solid the player's move for this step would run into, and when.
struct SolidHit
{
    std::size_t index = 0; // into getSolids()
    float time = 1.f;      // fraction of the step, 0..1
};

class RayLevel : public hitbox::Level
{
public:
    // The lab's field of boxes and tiles, the player sliding down-left along the floor.
    RayLevel();
    // Any set of solid boxes and a player box starting at `playerStart` (tests use this).
    RayLevel(std::vector<hitbox::Box> solids, sf::Vector2f playerStart);

    void handleInput(const Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // Task 1: the nearest solid the segment from `from` to `to` hits.
    RayHit castRay(hitbox::Vec2 from, hitbox::Vec2 to) const;

    // true: handle the contacts of a step in time order (the fix); false: in list order.
    void setTimeOrder(bool on);
    bool usesTimeOrder() const;
    // Where the player wants to go: each axis -1, 0 or 1 (like holding the arrow keys).
    void setMoveDirection(sf::Vector2f direction);

    const GameObject& getPlayer() const;
    const std::vector<hitbox::Box>& getSolids() const;
    const RayHit& getRay() const;
    // The solids the player's last step ran into, in the order they were handled.
    const std::vector<SolidHit>& getLastHits() const;
    // The player wanted to move in the last step but hardly moved (snagged or cornered).
    bool isStuck() const;

private:
    // Move the player by velocity * dt, sliding along what it runs into (tasks 2 and 3).
    void movePlayer(sf::Vector2f velocity, float dt);
    // Every solid the player's box would run into moving by `move`, with the time of each.
    std::vector<SolidHit> solidsInTheWay(sf::Vector2f move) const;
    // For ties in time: is solid a's centre nearer the player's centre than solid b's?
    bool isNearer(const SolidHit& a, const SolidHit& b) const;

    std::vector<hitbox::Box> solids;
    GameObject player;
    sf::Vector2f moveDirection{-1.f, 1.f}; // the demo: down-left along the tiled floor
    bool keyboardControl = false;          // a movement key has been pressed
    bool timeOrder = true;
    sf::Vector2f mouse;
    sf::Vector2f lastMouseReading;
    RayHit ray;
    std::vector<SolidHit> lastHits;
    bool stuck = false;              // wanted to move this step but hardly moved
    std::vector<sf::Vector2f> trail; // where the player has been, for the picture
    sf::Font font;
};
