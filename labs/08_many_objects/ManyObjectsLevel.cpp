#include "ManyObjectsLevel.h"

#include "BallOrder.h"
#include "Rules.h"

#include "hitbox/app/Input.h"
#include "hitbox/broadphase/GridBroadphase.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/platform/Platform.h"
#include "hitbox/platform/Prefetch.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace
{
// The world is hitbox::defaultWorldSize: balls above, the readout and the help bar below
// (so the debug view's grid never covers the numbers).
const hitbox::Box crowdArena{0.f, 0.f, hitbox::defaultWorldSize.x, 560.f};
const hitbox::Box tableSceneArena{0.f, 0.f, 600.f, 560.f};

// Crowd balls cover this fraction of the arena whatever their number, so each ball has a
// few neighbours at 100 balls and at 100,000 alike (the radius shrinks instead).
const float crowdCoverage = 0.12f;
const float smallestRadius = 0.5f;
const float crowdSpeedMin = 20.f;
const float crowdSpeedMax = 70.f;
const int crowdSizes[] = {100, 300, 1000, 3000, 10000, 30000, maxBalls};

const float tableBallRadius = 38.f;
const float tableBallSpeed = 90.f;
const int tableMinBalls = 2;
const int tableMaxBalls = 24;

const float shipRadius = 36.f;
const float shipSpeed = 70.f;
const float bulletRadius = 5.f;
const float bulletSpeed = 260.f;
const float bulletLifetime = 2.5f;
const float secondsBetweenShots = 0.1f;
const float pickupRadius = 11.f;
const int pickupsPerPile = 10;
const float pickupDrag = 1.5f; // per second: a knocked pickup slides to a stop

// [ and ] halve or double the grid's cell, between these multiples of the framework's rule.
const float smallestGridCellScale = 0.25f;
const float largestGridCellScale = 4.f;

hitbox::Vec2 fromAngle(float angle, float length)
{
    return {std::cos(angle) * length, std::sin(angle) * length};
}

} // namespace

ManyObjectsLevel::ManyObjectsLevel(const LabSettings& settings)
    : printTimingSeconds(settings.printTimingSeconds), stopWhenTooSlow(settings.stopWhenTooSlow),
      showTimings(settings.showTimings), threads(settings.threads)
{
    method = settings.method;
    random.seed(settings.seed);
    startScene(settings.scene, settings.balls);
}

void ManyObjectsLevel::startScene(Scene newScene, int count)
{
    scene = newScene;
    balls.clear();
    ownShipHits = 0;
    pickupBumps = 0;
    contacts = 0;
    candidatePairs.clear();
    table.reset(0);
    if (scene == Scene::Crowd)
        spawnCrowd(std::max(count, 0));
    else if (scene == Scene::PairTable)
        spawnPairTableBalls(std::clamp(count, tableMinBalls, tableMaxBalls));
    else
        spawnLayersScene();
    rebuildBroadphase();
}

void ManyObjectsLevel::setMethod(hitbox::BroadphaseMethod newMethod)
{
    method = newMethod;
    rebuildBroadphase();
}

void ManyObjectsLevel::setBalls(std::vector<Ball> newBalls)
{
    balls = std::move(newBalls);
    rebuildBroadphase();
}

void ManyObjectsLevel::rebuildBroadphase()
{
    stoppedAsTooSlow = false;
    collisionMilliseconds = 0.f;
    stepTiming.clear();
    if (method != hitbox::BroadphaseMethod::Grid)
    {
        broadphase = std::make_unique<TimedBroadphase>(hitbox::makeBroadphase(method));
        return;
    }
    // The grid's cell follows the balls' size and how crowded they are (the framework's rule,
    // GridCellRule.h), so a cell holds about the same number of balls at 100 or 100,000 and
    // the cost per ball stays flat. The lab lets you scale it ([ and ]) to see the trade-off:
    // small cells, many cells to fill; big cells, many pairs per cell.
    // Pairs in cell order: the lab responds to each pair once and needs no particular order,
    // and the grid skips sorting them (docs/performance.md).
    hitbox::GridSettings grid;
    grid.cellScale = gridCellScale;
    grid.order = hitbox::PairOrder::CellOrder;
    grid.threads = threads;
    broadphase = std::make_unique<TimedBroadphase>(std::make_unique<hitbox::GridBroadphase>(grid));
    warmUpBroadphase();
}

// The grid's first frames allocate its buffers (megabytes at 100,000 balls) and choose its
// shape: done here, when the scene starts, as a game does while loading, so that no step
// pays for it (the first step cost about 12 ms at 100,000 balls instead of about 4). The
// pairs go into the step's own list, emptied again, so its memory is there too: the first
// step has the most pairs of all (the balls start crowded, 35,000 pairs at 100,000 balls
// against about 15,600 later).
void ManyObjectsLevel::warmUpBroadphase()
{
    items.clear();
    for (const Ball& ball : balls)
        items.push_back(ball.item());
    for (int frame = 0; frame < 2; ++frame)
        broadphase->findPairs(items, candidatePairs);
    candidatePairs.clear(); // keeps its memory
}

Ball ManyObjectsLevel::makeBall(hitbox::Vec2 position, hitbox::Vec2 velocity, float radius,
                                BallKind kind, int owner) const
{
    Ball ball;
    ball.position = position;
    ball.velocity = velocity;
    ball.radius = radius;
    ball.kind = kind;
    ball.owner = owner;
    const CollisionFilter filter = filterFor(kind, owner);
    ball.layer = filter.layer;
    ball.mask = filter.mask;
    return ball;
}

void ManyObjectsLevel::spawnCrowd(int count)
{
    const hitbox::Box arena = crowdArena;
    const float averageRadius =
        count > 0 ? std::sqrt(arena.width * arena.height * crowdCoverage / (hitbox::pi * count))
                  : 1.f;
    std::uniform_real_distribution<float> x(0.f, 1.f);
    std::uniform_real_distribution<float> y(0.f, 1.f);
    std::uniform_real_distribution<float> size(0.7f, 1.3f);
    std::uniform_real_distribution<float> angle(0.f, 2.f * hitbox::pi);
    std::uniform_real_distribution<float> speed(crowdSpeedMin, crowdSpeedMax);
    balls.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
    {
        const float radius = std::max(smallestRadius, averageRadius * size(random));
        // Fully inside the arena, so no ball starts in a wall.
        const hitbox::Vec2 position{arena.left + radius + x(random) * (arena.width - 2.f * radius),
                                    arena.top + radius + y(random) * (arena.height - 2.f * radius)};
        balls.push_back(makeBall(position, fromAngle(angle(random), speed(random)), radius,
                                 BallKind::Plain, 0));
    }
    // Data locality: balls that are neighbours in the arena become neighbours in memory
    // (BallOrder.h), done once, as a game does while loading a level.
    sortBallsByTile(balls, arena, crowdSortTile);
}

void ManyObjectsLevel::spawnPairTableBalls(int count)
{
    // Every third ball is a pickup: with the rules of task 3, pickup-pickup cells of the
    // table stay untested.
    const hitbox::Box arena = tableSceneArena;
    const float margin = tableBallRadius;
    std::uniform_real_distribution<float> x(arena.left + margin, arena.left + arena.width - margin);
    std::uniform_real_distribution<float> y(arena.top + margin, arena.top + arena.height - margin);
    std::uniform_real_distribution<float> angle(0.f, 2.f * hitbox::pi);
    for (int i = 0; i < count; ++i)
    {
        const BallKind kind = i % 3 == 2 ? BallKind::Pickup : BallKind::Plain;
        balls.push_back(makeBall({x(random), y(random)}, fromAngle(angle(random), tableBallSpeed),
                                 tableBallRadius, kind, 0));
    }
}

void ManyObjectsLevel::spawnLayersScene()
{
    const hitbox::Box arena = crowdArena;
    balls.push_back(makeBall({arena.width * 0.25f, arena.height * 0.5f}, {0.f, shipSpeed},
                             shipRadius, BallKind::Ship, 0));
    balls.push_back(makeBall({arena.width * 0.75f, arena.height * 0.5f}, {0.f, -shipSpeed},
                             shipRadius, BallKind::Ship, 1));
    // Piles: pickups start on top of each other. With the rules they stay a pile.
    const hitbox::Vec2 piles[] = {{600.f, 110.f},  {600.f, 450.f}, {150.f, 460.f},
                                  {1050.f, 100.f}, {430.f, 280.f}, {770.f, 280.f}};
    std::uniform_real_distribution<float> offset(-pickupRadius * 1.5f, pickupRadius * 1.5f);
    for (const hitbox::Vec2 pile : piles)
        for (int i = 0; i < pickupsPerPile; ++i)
            balls.push_back(makeBall(pile + hitbox::Vec2(offset(random), offset(random)),
                                     {0.f, 0.f}, pickupRadius, BallKind::Pickup, 0));
    fireTimer = 0.f;
    fireAngle = 0.f;
}

void ManyObjectsLevel::handleInput(const hitbox::Input& input, float)
{
    if (input.isPressed(sf::Keyboard::Key::Num1))
        startScene(Scene::Crowd, 1000);
    if (input.isPressed(sf::Keyboard::Key::Num2))
    {
        // The table is brute force, so the readout's broadphase line matches it.
        method = hitbox::BroadphaseMethod::BruteForce;
        startScene(Scene::PairTable, 12);
    }
    if (input.isPressed(sf::Keyboard::Key::Num3))
        startScene(Scene::Layers, 0);
    if (input.isPressed(sf::Keyboard::Key::M))
        setMethod(static_cast<hitbox::BroadphaseMethod>((static_cast<int>(method) + 1) % 4));
    if (input.isPressed(sf::Keyboard::Key::LBracket) && gridCellScale > smallestGridCellScale)
    {
        gridCellScale /= 2.f;
        rebuildBroadphase();
    }
    if (input.isPressed(sf::Keyboard::Key::RBracket) && gridCellScale < largestGridCellScale)
    {
        gridCellScale *= 2.f;
        rebuildBroadphase();
    }

    const bool more = input.isPressed(sf::Keyboard::Key::Up);
    const bool fewer = input.isPressed(sf::Keyboard::Key::Down);
    const int count = static_cast<int>(balls.size());
    if (scene == Scene::PairTable && (more || fewer))
        startScene(scene, count + (more ? 1 : -1));
    if (scene == Scene::Crowd && more)
    {
        const int* next = std::upper_bound(std::begin(crowdSizes), std::end(crowdSizes), count);
        if (next != std::end(crowdSizes))
            startScene(scene, *next);
    }
    if (scene == Scene::Crowd && fewer)
    {
        const int* below = std::lower_bound(std::begin(crowdSizes), std::end(crowdSizes), count);
        if (below != std::begin(crowdSizes))
            startScene(scene, *(below - 1));
    }
}

void ManyObjectsLevel::applyLayersSceneRules(float dt)
{
    // Ships patrol up and down at a steady speed, whatever bumped them.
    for (Ball& ball : balls)
        if (ball.kind == BallKind::Ship)
            ball.velocity = {0.f, ball.velocity.y < 0.f ? -shipSpeed : shipSpeed};
        else if (ball.kind == BallKind::Pickup)
            ball.velocity *= std::max(0.f, 1.f - pickupDrag * dt);

    // Old bullets disappear: mark by age, then sweep (never erase while looping over them).
    for (Ball& ball : balls)
        ball.age += dt;
    balls.erase(std::remove_if(balls.begin(), balls.end(),
                               [](const Ball& ball) {
                                   return ball.kind == BallKind::Bullet &&
                                          ball.age > bulletLifetime;
                               }),
                balls.end());

    // Each ship fires from its own centre, so a bullet starts inside the ship that fired it:
    // only the rules keep the two apart.
    fireTimer += dt;
    if (fireTimer < secondsBetweenShots)
        return;
    fireTimer -= secondsBetweenShots;
    fireAngle += 0.45f;
    std::vector<Ball> shots;
    for (const Ball& ball : balls)
        if (ball.kind == BallKind::Ship)
        {
            const float angle = fireAngle + (ball.owner == 0 ? 0.f : hitbox::pi);
            shots.push_back(makeBall(ball.position, fromAngle(angle, bulletSpeed), bulletRadius,
                                     BallKind::Bullet, ball.owner));
        }
    balls.insert(balls.end(), shots.begin(), shots.end());
}

void ManyObjectsLevel::moveBalls(float dt)
{
    const hitbox::Box arena = getArena();
    const float right = arena.left + arena.width;
    const float bottom = arena.top + arena.height;
    for (Ball& ball : balls)
    {
        ball.position += ball.velocity * dt;
        if (ball.position.x - ball.radius < arena.left)
        {
            ball.position.x = arena.left + ball.radius;
            ball.velocity.x = std::abs(ball.velocity.x);
        }
        if (ball.position.x + ball.radius > right)
        {
            ball.position.x = right - ball.radius;
            ball.velocity.x = -std::abs(ball.velocity.x);
        }
        if (ball.position.y - ball.radius < arena.top)
        {
            ball.position.y = arena.top + ball.radius;
            ball.velocity.y = std::abs(ball.velocity.y);
        }
        if (ball.position.y + ball.radius > bottom)
        {
            ball.position.y = bottom - ball.radius;
            ball.velocity.y = -std::abs(ball.velocity.y);
        }
    }
}

// Real time between two update() calls, averaged. The steps of one frame run back to back,
// so the average is the real time one simulated step costs, drawing included: at
// 1000 / hitbox::stepsPerSecond ms (8.3) or less, the window keeps up.
void ManyObjectsLevel::measureRealTime()
{
    const float milliseconds = stepClock.restart().asSeconds() * 1000.f;
    if (stepsMeasured > 0)
        realStepMilliseconds +=
            (milliseconds - realStepMilliseconds) / (stepsMeasured < 10 ? 2.f : 30.f);
    ++stepsMeasured;
}

// One collision step's CPU time. With --print-timing the exact tests are also timed apart:
// the same circle tests again on this step's pairs, outside the step's own time, because
// timing each test inside the loop would cost more than the test. Every printTimingSeconds of
// simulated time, a line with the figures since the last one.
void ManyObjectsLevel::recordStepTime(double cpuSeconds)
{
    StepSample sample;
    sample.total = cpuSeconds;
    sample.broadphase = broadphase->lastSeconds();
    if (printTimingSeconds > 0.f)
    {
        const double begin = hitbox::platform::threadCpuSeconds();
        std::size_t touching = 0;
        for (std::size_t i = 0; i < candidatePairs.size(); ++i)
        {
            prefetchBallsOfPair(i + pairsPrefetchedAhead); // as the finished lab's loop does
            const hitbox::Pair& pair = candidatePairs[i];
            touching += hitbox::circleVsCircleContact(balls[pair.first].circle(),
                                                      balls[pair.second].circle())
                            .hit;
        }
        sample.exactTests = hitbox::platform::threadCpuSeconds() - begin;
        replayedContacts = touching; // kept, so the compiler cannot drop the loop
    }
    stepTiming.add(sample);
    collisionMilliseconds += (float(cpuSeconds * 1000.0) - collisionMilliseconds) / 30.f;
}

TimingSummary ManyObjectsLevel::getTimingSummary() const
{
    return stepTiming.summarise(stepBudgetMilliseconds);
}

void ManyObjectsLevel::update(float dt)
{
    measureRealTime();
    secondsSincePrint += dt;
    if (printTimingSeconds > 0.f && secondsSincePrint >= printTimingSeconds)
    {
        secondsSincePrint = 0.f;
        std::cout << timingLine() << std::endl;
        stepTiming.clear();
    }
    if (scene == Scene::Layers)
        applyLayersSceneRules(dt);
    moveBalls(dt);

    items.clear();
    for (Ball& ball : balls)
    {
        ball.responses = 0;
        items.push_back(ball.item());
    }
    contacts = 0;
    if (scene == Scene::PairTable)
        testEveryPair(items, table, layersMayCollide);

    bruteForceSkipped = method == hitbox::BroadphaseMethod::BruteForce &&
                        balls.size() > static_cast<std::size_t>(bruteForceBallLimit);
    if (bruteForceSkipped || stoppedAsTooSlow)
    {
        candidatePairs.clear();
        return;
    }
    // CPU time, so the figure does not depend on what else the machine runs; a second grid
    // thread's time beyond this one's is added (TimedBroadphase).
    const double begin = hitbox::platform::threadCpuSeconds();
    findPairsAndRespond();
    recordStepTime(hitbox::platform::threadCpuSeconds() - begin +
                   broadphase->lastWorkerExtraSeconds());
    // collisionMilliseconds is averaged over about 30 steps so the readout is steady enough.
    stoppedAsTooSlow = stopWhenTooSlow && collisionMilliseconds > slowStepMilliseconds;
}

// Prefetching (Prefetch.h): the grid hands over the pairs in cell order, which is not the order
// of the balls in memory, and at 100,000 balls (4.4 MB) a ball the cache does not hold makes
// the pair wait for main memory. Asked for pairsPrefetchedAhead pairs early, the balls are
// there when the loop gets to them (measured: docs/performance.md, tenth round).
void ManyObjectsLevel::prefetchBallsOfPair(std::size_t index) const
{
    if (index >= candidatePairs.size())
        return;
    const hitbox::Pair& pair = candidatePairs[index];
    hitbox::platform::prefetchObject(balls[pair.first]);
    hitbox::platform::prefetchObject(balls[pair.second]);
}

void ManyObjectsLevel::findPairsAndRespond()
{
    // BEGIN TASK 2: ask the broadphase for candidate pairs; respond to those that really touch
    broadphase->findPairs(items, candidatePairs);
    for (std::size_t i = 0; i < candidatePairs.size(); ++i)
    {
        // Not part of the task: the sheet's "Going further" (prefetching) explains it.
        prefetchBallsOfPair(i + pairsPrefetchedAhead);
        const hitbox::Pair& pair = candidatePairs[i];
        Ball& a = balls[pair.first];
        Ball& b = balls[pair.second];
        // The broadphase compared boxes: circles in overlapping boxes may still miss.
        const hitbox::Contact contact = hitbox::circleVsCircleContact(a.circle(), b.circle());
        if (contact.hit)
            respond(a, b, contact);
    }
    // STARTER TASK 2
    // candidatePairs.clear(); // no pairs asked for yet: every ball passes through the others
    // END TASK 2
}

void ManyObjectsLevel::respond(Ball& a, Ball& b, const hitbox::Contact& contact)
{
    bounceApart(a, b, contact);
    ++contacts;
    // Bookkeeping for the layers scene: count the responses its rules forbid.
    const bool shipAndBullet = (a.kind == BallKind::Ship && b.kind == BallKind::Bullet) ||
                               (a.kind == BallKind::Bullet && b.kind == BallKind::Ship);
    if (shipAndBullet && a.owner == b.owner)
        ++ownShipHits;
    if (a.kind == BallKind::Pickup && b.kind == BallKind::Pickup)
        ++pickupBumps;
}

Scene ManyObjectsLevel::getScene() const
{
    return scene;
}
hitbox::BroadphaseMethod ManyObjectsLevel::getMethod() const
{
    return method;
}
const std::vector<Ball>& ManyObjectsLevel::getBalls() const
{
    return balls;
}

hitbox::Box ManyObjectsLevel::getArena() const
{
    return scene == Scene::PairTable ? tableSceneArena : crowdArena;
}

std::size_t ManyObjectsLevel::getPairsTested() const
{
    if (bruteForceSkipped)
        return 0;
    return broadphase->stats().pairsTested;
}

std::size_t ManyObjectsLevel::getPairsOverlapping() const
{
    return candidatePairs.size();
}
std::size_t ManyObjectsLevel::getContacts() const
{
    return contacts;
}
bool ManyObjectsLevel::isBruteForceSkipped() const
{
    return bruteForceSkipped;
}
const PairTable& ManyObjectsLevel::getPairTable() const
{
    return table;
}
std::size_t ManyObjectsLevel::getOwnShipHits() const
{
    return ownShipHits;
}
std::size_t ManyObjectsLevel::getPickupBumps() const
{
    return pickupBumps;
}

std::string ManyObjectsLevel::getHelpText() const
{
    return "Up/Down balls  M method  [ ] grid cell  1 crowd  2 pair table  3 layers";
}

std::string ManyObjectsLevel::describeState() const
{
    const char* sceneNames[] = {"crowd", "pair table", "layers"};
    std::ostringstream text;
    text << sceneNames[static_cast<int>(scene)] << ", " << balls.size() << " balls, "
         << methodLabel(method) << ": ";
    if (bruteForceSkipped)
        text << "brute force skipped (over " << bruteForceBallLimit << " balls)";
    else if (stoppedAsTooSlow)
        text << "stopped: too slow";
    else
        text << getPairsTested() << " pairs tested, " << getPairsOverlapping()
             << " boxes overlapping, " << contacts << " circles touching";
    if (scene == Scene::PairTable)
        text << "; your loop tested " << table.testsMade() << " pairs";
    if (scene == Scene::Layers)
        text << "; bullets hit their own ship " << ownShipHits << " times, pickups bumped "
             << pickupBumps << " times";
    return text.str();
}

const char* methodLabel(hitbox::BroadphaseMethod method)
{
    switch (method)
    {
    case hitbox::BroadphaseMethod::BruteForce:
        return "brute force";
    case hitbox::BroadphaseMethod::SortAndSweep:
        return "sort and sweep";
    case hitbox::BroadphaseMethod::Grid:
        return "grid";
    case hitbox::BroadphaseMethod::Quadtree:
        return "quadtree";
    }
    return "?";
}

hitbox::BroadphaseMethod parseMethod(const std::string& text)
{
    if (text == "brute" || text == "brute-force")
        return hitbox::BroadphaseMethod::BruteForce;
    if (text == "sweep" || text == "sort-and-sweep")
        return hitbox::BroadphaseMethod::SortAndSweep;
    if (text == "grid")
        return hitbox::BroadphaseMethod::Grid;
    if (text == "quadtree")
        return hitbox::BroadphaseMethod::Quadtree;
    throw std::invalid_argument("--method must be brute, sweep, grid or quadtree, not '" + text +
                                "'");
}

Scene parseScene(const std::string& text)
{
    if (text == "crowd")
        return Scene::Crowd;
    if (text == "table")
        return Scene::PairTable;
    if (text == "layers")
        return Scene::Layers;
    throw std::invalid_argument("--scene must be crowd, table or layers, not '" + text + "'");
}
