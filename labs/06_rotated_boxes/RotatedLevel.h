// RotatedLevel.h - rotated boxes (and one capsule) that you drag with the mouse and turn
// with the mouse wheel, tested by the separating axis theorem (Sat.h).
//
// For the shape you hold, the picture shows what SAT found against its nearest neighbour:
// when apart, the separating line and the two shadows on the axis with the widest gap; when
// overlapping, the shadows on the axis of least overlap and the minimum translation vector
// (MTV): the shortest move that gets the held shape out.
#pragma once

#include "Sat.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"
#include "hitbox/geometry/Capsule.h"

#include <memory>
#include <vector>

// A box turned about its centre, or a capsule: then body.halfSize.x is half the length of its
// middle segment and body.halfSize.y its radius.
struct Shape
{
    hitbox::OrientedBox body;
    bool isCapsule = false;

    hitbox::Polygon polygon() const; // boxes only
    hitbox::Capsule capsule() const; // capsules only
};

// How the held shape meets one other shape this step.
struct PairView
{
    std::size_t other = 0;
    bool overlapping = false;
    hitbox::Vec2 axis;          // separating axis, or the MTV direction (out of `other`)
    float gap = 0.f;            // > = 0 when apart, -depth when overlapping
    bool boundsOverlap = false; // their axis-aligned bounding boxes overlap
    bool hasShadows = false;    // box vs box: the shadows below can be drawn
    Shadow heldShadow;          // the held shape's shadow on `axis`
    Shadow otherShadow;
};

class RotatedLevel : public hitbox::Level
{
public:
    RotatedLevel();
    explicit RotatedLevel(std::vector<Shape> shapes); // shape 0 starts held

    // Turn the held shape by itself, this many degrees a second (0: only the wheel turns
    // it). The lecture's animation uses it to show the SAT axes turning with the shape.
    void setSpin(float degreesPerSecond);

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

    // The mouse wheel turns the held shape by this many degrees a notch (task 3).
    static constexpr float degreesPerNotch = 15.f;

    const std::vector<Shape>& getShapes() const;
    std::size_t getHeld() const;
    // How the held shape meets every other shape (filled in by update()).
    const std::vector<PairView>& getPairs() const;
    // Is shape i overlapping anything?
    bool isOverlapping(std::size_t i) const;
    // The pair drawn with its shadows: the nearest other shape.
    const PairView* getNearestPair() const;
    // Box pairs tested by the framework's hitbox::findSeparatingAxis instead of your Sat.cpp
    // (key F: compare the two; the tests of tasks 3 and 4 use it, so they need no task 1 or 2).
    void setFrameworkSat(bool on);
    bool usesFrameworkSat() const;

private:
    PairView testPair(std::size_t held, std::size_t other) const;
    void turnHeld(float notches);
    void pushHeldOut();

    std::vector<Shape> shapes;
    std::size_t held = 0;
    bool dragging = false;
    bool frameworkSat = false;
    hitbox::Vec2 grabOffset;
    float spinDegreesPerSecond = 0.f;
    std::vector<PairView> pairs;
    std::vector<bool> overlapping;
    hitbox::LazyFont font; // read by the first render(): tests need no font file
};
