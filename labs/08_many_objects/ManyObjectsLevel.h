// ManyObjectsLevel.h - lab 8: thousands of balls, and the broadphase that keeps them fast.
//
// Three scenes:
//   1 crowd       100 to 100,000 balls; switch the broadphase and watch the pair counts and
//                 the milliseconds: brute force explodes (n^2), the grid stays flat.
//   2 pair table  a dozen big numbered balls and the n x n table of every pair beside them, filled
//                 by your brute-force loop (task 1).
//   3 layers      two ships firing bullets, piles of pickups: layers and masks (task 3) decide
//                 which pairs are ever tested.
// The rules run in update(); render() only reads state, so tests run it with no window.
#pragma once

#include "Ball.h"
#include "PairTable.h"
#include "StepTiming.h"
#include "TimedBroadphase.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"
#include "hitbox/broadphase/Broadphase.h"

#include <SFML/Graphics/Vertex.hpp>
#include <SFML/System/Clock.hpp>
#include <SFML/System/Time.hpp>

#include <cstddef>
#include <memory>
#include <random>
#include <string>
#include <vector>

enum class Scene
{
    Crowd,
    PairTable,
    Layers
};

struct LabSettings
{
    Scene scene = Scene::Crowd;
    int balls = 1000; // crowd: any count; pair table: 2 to 24
    hitbox::BroadphaseMethod method = hitbox::BroadphaseMethod::Grid;
    unsigned seed = 1;
    // > 0: print a timing line every this many simulated seconds (window or --headless).
    float printTimingSeconds = 0.f;
    // The grid's threads: 1 or 2 (2 splits it in halves from 20,000 balls, see GridSettings).
    // Both give the same pairs in the same order, so the same balls step after step.
    int threads = 2;
    bool stopWhenTooSlow = false; // the wall-clock guard below: for a window, never headless
    // The readout's timing line (CPU and real time per step); off in a --screenshot picture,
    // which must be the same on every run (hitbox::Options::repeatablePicture).
    bool showTimings = true;
};

// What one collision step may cost to keep up with the fixed step: 1000 / 120 = 8.33 ms of
// CPU time (--print-timing counts the steps over it).
constexpr double stepBudgetMilliseconds = 1000.0 / double(hitbox::stepsPerSecond);

// The most balls a scene can hold (Up in the crowd scene stops here too).
constexpr int maxBalls = 100000;

// A new crowd is sorted into strips this many pixels tall (data locality, BallOrder.h). At
// 100,000 balls a strip holds about 2,900 balls (130 KB), so a ball's neighbours in the strips
// above and below it are still in the processor's cache (2 MB on the machine it was measured on).
constexpr float crowdSortTile = 16.f;

// The pair loop asks for the balls of the pair this many places ahead (prefetching, Ericson's
// Real-Time Collision Detection, 13.6): far enough ahead that they arrive before the loop gets
// there. 6, 12 and 24 measured the same within the noise (docs/performance.md, tenth round).
constexpr std::size_t pairsPrefetchedAhead = 12;

// Above this many balls brute force is not run: 3,000 balls already mean 4.5 million box
// tests every step, 120 steps a second, and the window would stop answering. A debug build
// (no optimisation) is about ten times slower, so it stops sooner. The readout says what
// brute force would have cost.
#ifdef NDEBUG
constexpr int bruteForceBallLimit = 3000;
#else
constexpr int bruteForceBallLimit = 1000;
#endif

// In a window (LabSettings::stopWhenTooSlow), any method whose collision step averages more
// than this (CPU time) stops until the method or the number of balls changes: at 120 steps a
// second the window would hardly move. Headless runs never stop, so their results are the
// same on every machine. (It cannot
// happen in a test's few steps: the average starts at 0 and needs a dozen slow steps.)
constexpr float slowStepMilliseconds = 40.f;

// Every value a step changes and no step rebuilds, in one plain struct: saveState copies it
// whole and restoreState assigns it back (LevelSnapshot.cpp), so a value added here is rewound
// without another line. The rest of the level is rebuilt (the broadphase, this step's items
// and pairs) or only measured (timings).
struct ManyObjectsState
{
    Scene scene = Scene::Crowd;
    hitbox::BroadphaseMethod method = hitbox::BroadphaseMethod::Grid;
    std::mt19937 random;
    std::vector<Ball> balls;
    PairTable table;
    std::size_t contacts = 0;
    bool bruteForceSkipped = false;
    std::size_t ownShipHits = 0;
    std::size_t pickupBumps = 0;
    float gridCellScale = 1.f; // grid cell = the framework's cell rule (GridCellRule.h) * this
    float fireTimer = 0.f;
    float fireAngle = 0.f;
    float secondsSincePrint = 0.f; // simulated
};

// The level inherits its state privately: the rules read `balls`, `table`... as plain
// members, and only the snapshot sees the whole.
class ManyObjectsLevel : public hitbox::Level, private ManyObjectsState
{
public:
    explicit ManyObjectsLevel(const LabSettings& settings = {});

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // Start a scene afresh with `balls` balls (ignored by the layers scene).
    void startScene(Scene scene, int balls);
    void setMethod(hitbox::BroadphaseMethod method);
    // Replace the balls, e.g. a test's hand-made scene. Layers and masks are kept as given.
    void setBalls(std::vector<Ball> newBalls);

    Scene getScene() const;
    hitbox::BroadphaseMethod getMethod() const;
    const std::vector<Ball>& getBalls() const;
    hitbox::Box getArena() const;
    // This step: pairs the broadphase compared, pairs whose boxes overlap, and pairs whose
    // circles really touched (each one got one response).
    std::size_t getPairsTested() const;
    std::size_t getPairsOverlapping() const;
    std::size_t getContacts() const;
    bool isBruteForceSkipped() const;
    // True when the method was stopped for being too slow (see slowStepMilliseconds).
    bool isStoppedAsTooSlow() const;
    // CPU time of the collision steps since the last timing line (all of them without
    // --print-timing), against the budget of one step.
    TimingSummary getTimingSummary() const;
    // The table your loop filled this step (pair table scene only).
    const PairTable& getPairTable() const;
    // Since the scene started: responses the rules forbid (both must stay 0 with task 3).
    std::size_t getOwnShipHits() const;
    std::size_t getPickupBumps() const;

    // For rewinding (hitbox::RewindLevel; LevelSnapshot.cpp): the balls and every other value
    // a step changes. Restoring builds the broadphase afresh for the restored balls.
    std::unique_ptr<hitbox::LevelState> saveState() const override;
    void restoreState(const hitbox::LevelState& state) override;

private:
    void spawnCrowd(int count);
    void spawnPairTableBalls(int count);
    void spawnLayersScene();
    Ball makeBall(hitbox::Vec2 position, hitbox::Vec2 velocity, float radius, BallKind kind,
                  int owner) const;
    void applyLayersSceneRules(float dt);
    void moveBalls(float dt);
    void rebuildBroadphase();
    void warmUpBroadphase();
    void findPairsAndRespond();
    // Asks the cache for the two balls of candidatePairs[index] (nothing past the last pair).
    void prefetchBallsOfPair(std::size_t index) const;
    void respond(Ball& a, Ball& b, const hitbox::Contact& contact);

    void drawBalls(sf::RenderTarget& target) const;
    void drawPairTable(sf::RenderTarget& target) const;
    void drawReadout(sf::RenderTarget& target) const;
    void measureRealTime();
    void recordStepTime(double cpuSeconds);
    // The readout's numbers on one line, for --print-timing.
    std::string timingLine() const;

    Scene scene = Scene::Crowd;
    hitbox::BroadphaseMethod method = hitbox::BroadphaseMethod::Grid;
    std::unique_ptr<TimedBroadphase> broadphase; // the method, measuring its own CPU time
    std::vector<hitbox::BroadphaseItem> items;   // balls[i].item(), rebuilt every step
    std::vector<hitbox::Pair> candidatePairs;    // the broadphase's answer this step
    bool stoppedAsTooSlow = false;
    float collisionMilliseconds = 0.f; // CPU time in findPairsAndRespond, averaged over steps
    float printTimingSeconds = 0.f;
    StepTiming stepTiming;            // every collision step since the last timing line
    std::size_t replayedContacts = 0; // the exact tests timed apart (recordStepTime)
    bool stopWhenTooSlow = false;
    bool showTimings = true;
    int threads = 2;

    // Real time, measured in update(): the readout shows it, --print-timing prints it.
    sf::Clock stepClock;              // restarted by every update()
    float realStepMilliseconds = 0.f; // real time per simulated step, drawing included
    int stepsMeasured = 0;

    hitbox::LazyFont font; // read by the first render(): tests need no font file
    // The balls' triangles, refilled by every render(): kept so a frame reuses last frame's
    // memory instead of growing a new array of 60,000 vertices (drawing only, not state).
    mutable std::vector<sf::Vertex> ballVertices;
};

// "brute force", "sort and sweep", "grid", "quadtree": the readout's words.
const char* methodLabel(hitbox::BroadphaseMethod method);
// Reads "brute", "sweep", "grid" or "quadtree" (also the full names); throws
// std::invalid_argument otherwise.
hitbox::BroadphaseMethod parseMethod(const std::string& text);
// Reads "crowd", "table" or "layers"; throws std::invalid_argument otherwise.
Scene parseScene(const std::string& text);
