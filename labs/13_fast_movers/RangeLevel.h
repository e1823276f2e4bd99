// RangeLevel.h - three lanes of bullets fired at a thin wall, faster every shot.
//
// The top lane moves by plain discrete steps, the middle one by sub-steps (task 1), the
// bottom one with a speculative contact (task 2). Each shot is 1.5 times as fast as the
// last, up to topSpeed, where it stays (said on screen); the readout counts, per lane, the
// shots that went through the wall. F1 shows each lane's next move, its sub-steps or its
// measured gap, and the bullets' state against the wall.
#pragma once

#include "FastMove.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"

#include <string>

class RangeLevel : public hitbox::Level
{
public:
    static constexpr int laneCount = 3;
    static constexpr float firstSpeed = 600.f; // pixels per second
    static constexpr float speedUp = 1.5f;     // each shot is this much faster
    static constexpr float maxSubStep = 8.f;   // pixels: less than wall plus bullet width
    // The fastest shot, pixels per second: a step then moves about 8,000 px, well inside
    // Hitbox's exact range of coordinates (1e6 px, hitbox/geometry/Range.h). Shots stay at
    // this speed once they reach it; the help line says so.
    static constexpr float topSpeed = 1e6f;

    // The speed of the shot after one at `speed`: speedUp times faster, never above topSpeed.
    static float nextShotSpeed(float speed);

    RangeLevel();

    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    int getThroughCount(int lane) const;
    float getSpeed() const;

private:
    void fire();

    Box wall;
    Box bullets[laneCount];
    bool flying[laneCount] = {};
    int throughCount[laneCount] = {};
    int shots = 0;
    float speed = firstSpeed;
    hitbox::LazyFont font; // the lanes' labels; read by the first render(): tests need no font
};
