// CrowdLevel.h - a crowd of drifting boxes; the overlapping ones turn red.
//
// Each step the level finds the overlapping pairs with one of your searches (M switches:
// brute force, sort and sweep, grid) and the readout shows how many exact tests it ran.
// Every search must find the same red boxes; only the count of tests changes.
#pragma once

#include "BroadPhase.h"

#include "hitbox/app/Level.h"

#include <memory>
#include <random>
#include <string>
#include <vector>

class CrowdLevel : public hitbox::Level
{
public:
    enum class Method
    {
        BruteForce,
        SortAndSweep,
        Grid
    };
    // Cells of the grid, in world pixels: a little more than the largest box.
    static constexpr float cellSize = 48.f;
    // F1 in sort and sweep: a line crosses the world at this speed, and the boxes open where
    // it is (left <= x < right) are outlined: the list the sweep keeps at that moment.
    static constexpr float sweepLineSpeed = 150.f;

    CrowdLevel(int boxCount, unsigned seed);

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

    // The last step's search: the pairs it found and how many exact tests it ran.
    [[nodiscard]] const std::vector<Pair>& getLastPairs() const;
    [[nodiscard]] long long getLastExactTests() const;

private:
    std::vector<Box> boxes;
    std::vector<float> speedX;
    std::vector<float> speedY;
    Method method = Method::SortAndSweep;
    std::vector<Pair> lastPairs;
    long long lastExactTests = 0;
    std::vector<bool> overlapping; // box i is in one of lastPairs (drawn red)
    float sweepLineX = 0.f;
};
