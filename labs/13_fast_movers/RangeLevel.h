// RangeLevel.h - three lanes of bullets fired at a thin wall, faster every shot.
//
// The top lane moves by plain discrete steps, the middle one by sub-steps (task 1), the
// bottom one with a speculative contact (task 2). Each shot is 1.5 times as fast as the
// last; the readout counts, per lane, the shots that went through the wall.
#pragma once

#include "FastMove.h"

#include "hitbox/app/Level.h"

#include <string>

class RangeLevel : public hitbox::Level
{
public:
    static constexpr int laneCount = 3;
    static constexpr float firstSpeed = 600.f; // pixels per second
    static constexpr float speedUp = 1.5f;     // each shot is this much faster
    static constexpr float maxSubStep = 8.f;   // pixels: less than wall plus bullet width

    RangeLevel();

    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    int getThroughCount(int lane) const;

private:
    void fire();

    Box wall;
    Box bullets[laneCount];
    bool flying[laneCount] = {};
    int throughCount[laneCount] = {};
    int shots = 0;
    float speed = firstSpeed;
};
