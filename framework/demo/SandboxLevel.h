// SandboxLevel.h - the framework demo: move a box or a circle with the mouse over a few
// shapes and watch the tests answer (F1: outlines turn hatched vermillion where they collide,
// dashed yellow where edges only touch; contact normals appear).
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/objects/GameObject.h"

#include <vector>

class SandboxLevel : public hitbox::Level
{
public:
    SandboxLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

private:
    struct Obstacle
    {
        hitbox::GameObject shape;
        bool isCircle = false;
        bool overlapping = false;
        hitbox::Contact contact; // how the cursor shape overlaps it (hit, normal, depth)
    };

    void addObstacle(sf::Vector2f position, sf::Vector2f size, bool isCircle);
    hitbox::Contact testCursorAgainst(Obstacle& obstacle);
    // Its box's edges meet another obstacle's box with no shared area (boxes only).
    bool edgesMeetAnother(const Obstacle& obstacle) const;
    // What the debug view shows for it (DebugRenderer.h's three states).
    hitbox::DebugState stateOf(const Obstacle& obstacle) const;

    std::vector<Obstacle> obstacles;
    hitbox::GameObject cursor;
    bool cursorIsCircle = false;
    // Where the cursor shape starts (over two shapes, so a --screenshot shows contacts);
    // it follows the mouse once the mouse moves.
    sf::Vector2f mouse{560.f, 250.f};
    sf::Vector2f lastMouseReading;
};
