// Grading tests for lab 8 (many objects). Each suite is named after the task it checks;
// every task has tests that fail on the unmodified exercise. No window is needed.
#include "ManyObjectsLevel.h"
#include "PairTable.h"
#include "Rules.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Overlap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace
{
using hitbox::BroadphaseItem;
using hitbox::BroadphaseMethod;

const BroadphaseMethod allMethods[] = {BroadphaseMethod::BruteForce, BroadphaseMethod::SortAndSweep,
                                       BroadphaseMethod::Grid, BroadphaseMethod::Quadtree};

// `count` random boxes in a 400 x 400 area, sizes 5 to 60: a few overlaps each.
std::vector<BroadphaseItem> randomBoxes(unsigned seed, int count)
{
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> position(0.f, 400.f);
    std::uniform_real_distribution<float> size(5.f, 60.f);
    std::vector<BroadphaseItem> items;
    for (int i = 0; i < count; ++i)
        items.push_back({{position(random), position(random), size(random), size(random)}});
    return items;
}

// The answer worked out the slow, obvious way: every (i, j) with i < j, in order.
std::vector<std::pair<std::uint32_t, std::uint32_t>>
referenceOverlaps(const std::vector<BroadphaseItem>& items, bool obeyLayers)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
    for (std::uint32_t i = 0; i < items.size(); ++i)
        for (std::uint32_t j = i + 1; j < items.size(); ++j)
        {
            const bool allowed =
                (items[i].layer & items[j].mask) && (items[j].layer & items[i].mask);
            if ((allowed || !obeyLayers) && hitbox::boxVsBox(items[i].box, items[j].box))
                found.emplace_back(i, j);
        }
    return found;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> asPairs(const std::vector<hitbox::Pair>& pairs)
{
    std::vector<std::pair<std::uint32_t, std::uint32_t>> result;
    for (const hitbox::Pair& found : pairs)
        result.emplace_back(found.first, found.second);
    std::sort(result.begin(), result.end());
    return result;
}

Ball plainBall(hitbox::Vec2 position, hitbox::Vec2 velocity, float radius)
{
    Ball ball;
    ball.position = position;
    ball.velocity = velocity;
    ball.radius = radius;
    return ball;
}

// How many pairs of balls have circles that share area.
std::size_t touchingCircles(const std::vector<Ball>& balls, std::vector<int>& partners)
{
    partners.assign(balls.size(), 0);
    std::size_t count = 0;
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j)
            if (hitbox::circleVsCircle(balls[i].circle(), balls[j].circle()))
            {
                ++count;
                ++partners[i];
                ++partners[j];
            }
    return count;
}

// A seeded scene of about 750 balls (below the debug build's brute-force limit) in 30-pixel
// cells of a 900 x 540 area inside the arena, far enough apart that responses never
// chain: each cell is empty, one ball, two touching balls, or two diagonal balls whose boxes
// overlap but whose circles do not.
std::vector<Ball> separatePairsScene(unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> what(0, 9);
    std::vector<Ball> balls;
    const float radius = 5.f;
    for (int row = 0; row < 18; ++row)
        for (int column = 0; column < 30; ++column)
        {
            const hitbox::Vec2 center{15.f + 30.f * column, 15.f + 30.f * row};
            const int kind = what(random);
            if (kind < 4)
                balls.push_back(plainBall(center, {}, radius));
            else if (kind < 7)
            {
                balls.push_back(plainBall(center - hitbox::Vec2(3.f, 1.f), {}, radius));
                balls.push_back(plainBall(center + hitbox::Vec2(3.f, 1.f), {}, radius));
            }
            else if (kind < 9)
            {
                balls.push_back(plainBall(center - hitbox::Vec2(3.8f, 3.8f), {}, radius));
                balls.push_back(plainBall(center + hitbox::Vec2(3.8f, 3.8f), {}, radius));
            }
        }
    return balls;
}

// The tests' own game rules, so the pair loop (task 1) is checked whatever state the lab's
// rules (task 3) are in.
bool anyPair(const BroadphaseItem&, const BroadphaseItem&)
{
    return true;
}

bool layerInTheOthersMask(const BroadphaseItem& a, const BroadphaseItem& b)
{
    return (a.layer & b.mask) != 0 && (b.layer & a.mask) != 0;
}

} // namespace

// ---- Task 1: the pair table (brute-force loop) ----

TEST(Task1PairTable, TestsEveryPairExactlyOnce)
{
    const std::vector<BroadphaseItem> items = randomBoxes(1, 20);
    PairTable table;
    testEveryPair(items, table, anyPair);
    EXPECT_EQ(table.testsMade(), 20u * 19u / 2u) << "20 objects make 20*19/2 = 190 pairs";
    // ASSERT: the first wrong cell is enough (a wrong loop gets hundreds of them wrong).
    for (std::uint32_t row = 0; row < 20; ++row)
        for (std::uint32_t column = 0; column < 20; ++column)
            ASSERT_EQ(table.timesTested(row, column), column > row ? 1 : 0)
                << "cell (" << row << ", " << column << "): test each pair once, only i < j";
}

TEST(Task1PairTable, FindsTheSameOverlapsAsTheReferenceOnSeededScenes)
{
    for (unsigned seed = 1; seed <= 50; ++seed)
    {
        const std::vector<BroadphaseItem> items = randomBoxes(seed, 30);
        PairTable table;
        testEveryPair(items, table, anyPair);
        // ASSERT: the first scene that differs is enough (not fifty like it).
        ASSERT_EQ(asPairs(table.overlappingPairs()), referenceOverlaps(items, true))
            << "scene with seed " << seed;
        ASSERT_FALSE(table.overlappingPairs().empty()) << "scene with seed " << seed;
    }
}

TEST(Task1PairTable, TouchingBoxesAreNotAPair)
{
    const std::vector<BroadphaseItem> items = {
        {{0.f, 0.f, 10.f, 10.f}}, {{10.f, 0.f, 10.f, 10.f}}, {{5.f, 5.f, 10.f, 10.f}}};
    PairTable table;
    testEveryPair(items, table, anyPair);
    EXPECT_EQ(table.testsMade(), 3u);
    EXPECT_FALSE(table.isOverlapping(0, 1)) << "boxes that only touch edges share no area";
    EXPECT_TRUE(table.isOverlapping(0, 2));
    EXPECT_TRUE(table.isOverlapping(1, 2));
}

TEST(Task1PairTable, TheSceneShowsTheLoopFillingTheTable)
{
    LabSettings settings;
    settings.scene = Scene::PairTable;
    settings.balls = 12;
    ManyObjectsLevel level(settings);
    hitbox::simulate(level, 1);
    // Some balls are pickups, so the rules of task 3 may skip some of the 66 pairs. The count
    // asks task 3's layersMayCollide, whatever it answers: this test checks task 1's loop in
    // the scene, so a mistake in the rules (even one that allows no pair) costs task 3 alone.
    std::size_t allowed = 0;
    const std::vector<Ball>& balls = level.getBalls();
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j)
            allowed += layersMayCollide(balls[i].item(), balls[j].item()) ? 1 : 0;
    EXPECT_EQ(level.getPairTable().size(), 12u);
    EXPECT_EQ(level.getPairTable().testsMade(), allowed);
}

TEST(Task1PairTable, SkipsThePairsTheRuleRulesOutBeforeTesting)
{
    for (unsigned seed = 1; seed <= 20; ++seed)
    {
        // Even items are on layer 2 and ignore layer 2 (as pickups ignore pickups).
        std::vector<BroadphaseItem> items = randomBoxes(seed, 30);
        for (std::size_t i = 0; i < items.size(); i += 2)
        {
            items[i].layer = 2u;
            items[i].mask = ~2u;
        }
        PairTable table;
        testEveryPair(items, table, layerInTheOthersMask);
        // ASSERT: the first scene that differs is enough (not twenty like it).
        ASSERT_EQ(table.testsMade(), 30u * 29u / 2u - 15u * 14u / 2u)
            << "seed " << seed << ": the 105 pairs the rule rules out are never tested";
        ASSERT_EQ(asPairs(table.overlappingPairs()), referenceOverlaps(items, true))
            << "seed " << seed;
    }
}

// ---- Task 2: use the broadphase, respond once to each pair that really touches ----

TEST(Task2RespondToPairs, TwoOverlappingBallsRespondOnceAndMoveApart)
{
    ManyObjectsLevel level;
    level.setBalls({plainBall({300.f, 300.f}, {50.f, 0.f}, 20.f),
                    plainBall({330.f, 300.f}, {-50.f, 0.f}, 20.f)});
    level.update(hitbox::stepSeconds);
    const std::vector<Ball>& balls = level.getBalls();
    EXPECT_EQ(level.getContacts(), 1u);
    EXPECT_EQ(balls[0].responses, 1) << "one response per pair, not one per ball or per test";
    EXPECT_EQ(balls[1].responses, 1);
    EXPECT_LT(balls[0].velocity.x, 0.f) << "the left ball bounces back to the left";
    EXPECT_GT(balls[1].velocity.x, 0.f) << "the right ball bounces back to the right";
    EXPECT_FALSE(hitbox::circleVsCircle(balls[0].circle(), balls[1].circle()))
        << "after the response they no longer overlap";
}

TEST(Task2RespondToPairs, BallsWhoseBoxesOverlapButCirclesDoNotAreLeftAlone)
{
    // Diagonal neighbours: the boxes share a corner area, the circles are 4 px apart.
    ManyObjectsLevel level;
    level.setBalls(
        {plainBall({300.f, 300.f}, {0.f, 0.f}, 20.f), plainBall({331.f, 331.f}, {0.f, 0.f}, 20.f)});
    level.update(hitbox::stepSeconds);
    EXPECT_EQ(level.getPairsOverlapping(), 1u) << "the broadphase reports the boxes";
    EXPECT_EQ(level.getContacts(), 0u) << "but only circles that touch get a response";
    EXPECT_EQ(level.getBalls()[0].responses, 0);
}

TEST(Task2RespondToPairs, EveryMethodRespondsOnceToEveryTouchingPairOnSeededScenes)
{
    for (unsigned seed = 1; seed <= 5; ++seed)
    {
        const std::vector<Ball> scene = separatePairsScene(seed);
        std::vector<int> partners;
        const std::size_t expected = touchingCircles(scene, partners);
        ASSERT_GT(expected, 100u);
        ASSERT_LE(scene.size(), static_cast<std::size_t>(bruteForceBallLimit));
        for (BroadphaseMethod method : allMethods)
        {
            LabSettings settings;
            settings.method = method;
            ManyObjectsLevel level(settings);
            level.setBalls(scene);
            level.update(0.f); // no movement: the pairs are the ones counted above
            EXPECT_EQ(level.getContacts(), expected)
                << hitbox::toString(method) << ", seed " << seed;
            int wrongBalls = 0;
            for (std::size_t i = 0; i < partners.size(); ++i)
                wrongBalls += level.getBalls()[i].responses != partners[i] ? 1 : 0;
            EXPECT_EQ(wrongBalls, 0) << hitbox::toString(method) << ", seed " << seed
                                     << ": each ball responds once per ball it touches";
        }
        if (HasFailure())
            return; // the first scene that fails is enough (not five like it)
    }
}

TEST(Task2RespondToPairs, AHeadOnPairNeverPassesThrough)
{
    ManyObjectsLevel level;
    level.setBalls({plainBall({200.f, 300.f}, {200.f, 0.f}, 15.f),
                    plainBall({500.f, 300.f}, {-200.f, 0.f}, 15.f)});
    for (int step = 0; step < 240; ++step)
    {
        level.update(hitbox::stepSeconds);
        ASSERT_LT(level.getBalls()[0].position.x, level.getBalls()[1].position.x)
            << "step " << step << ": the balls went through each other";
    }
}

TEST(Task2RespondToPairs, PairsTheLayersRuleOutNeverRespond)
{
    // Two overlapping pairs: one whose layers rule it out (set here, not by task 3's
    // rules: the broadphase applies the layers itself), and one that collides.
    Ball ignoring = plainBall({300.f, 300.f}, {}, 20.f);
    ignoring.layer = 2u;
    ignoring.mask = ~2u;
    Ball alsoIgnoring = ignoring;
    alsoIgnoring.position.x += 20.f;
    const std::vector<Ball> scene = {ignoring, alsoIgnoring, plainBall({300.f, 400.f}, {}, 20.f),
                                     plainBall({320.f, 400.f}, {}, 20.f)};
    for (BroadphaseMethod method : allMethods)
    {
        LabSettings settings;
        settings.method = method;
        ManyObjectsLevel level(settings);
        level.setBalls(scene);
        level.update(0.f);
        const std::vector<Ball>& balls = level.getBalls();
        EXPECT_EQ(level.getContacts(), 1u) << hitbox::toString(method);
        EXPECT_EQ(balls[0].responses + balls[1].responses, 0)
            << hitbox::toString(method) << ": their layers rule the pair out";
        EXPECT_EQ(balls[2].responses + balls[3].responses, 2) << hitbox::toString(method);
    }
}

// ---- Task 3: layers and masks ----

namespace
{
BroadphaseItem itemFor(BallKind kind, int owner)
{
    const CollisionFilter filter = filterFor(kind, owner);
    return {{0.f, 0.f, 10.f, 10.f}, filter.layer, filter.mask};
}
} // namespace

TEST(Task3LayersAndMasks, BothSidesMustAgree)
{
    const BroadphaseItem wantsB{{}, 1u, 2u};
    const BroadphaseItem ignoresA{{}, 2u, 0u};
    const BroadphaseItem acceptsA{{}, 2u, 1u};
    EXPECT_FALSE(layersMayCollide(wantsB, ignoresA));
    EXPECT_FALSE(layersMayCollide(ignoresA, wantsB));
    EXPECT_TRUE(layersMayCollide(wantsB, acceptsA));
    EXPECT_TRUE(layersMayCollide(acceptsA, wantsB));
}

TEST(Task3LayersAndMasks, BulletsIgnoreTheirOwnerButHitTheOtherShip)
{
    for (int owner = 0; owner < 2; ++owner)
    {
        const int other = 1 - owner;
        EXPECT_FALSE(
            layersMayCollide(itemFor(BallKind::Bullet, owner), itemFor(BallKind::Ship, owner)))
            << "owner " << owner;
        EXPECT_TRUE(
            layersMayCollide(itemFor(BallKind::Bullet, owner), itemFor(BallKind::Ship, other)))
            << "owner " << owner;
        EXPECT_FALSE(
            layersMayCollide(itemFor(BallKind::Bullet, owner), itemFor(BallKind::Bullet, other)))
            << "bullets pass through bullets";
    }
}

TEST(Task3LayersAndMasks, PickupsIgnoreEachOtherButNotShipsOrBullets)
{
    EXPECT_FALSE(layersMayCollide(itemFor(BallKind::Pickup, 0), itemFor(BallKind::Pickup, 0)));
    EXPECT_TRUE(layersMayCollide(itemFor(BallKind::Pickup, 0), itemFor(BallKind::Ship, 1)));
    EXPECT_TRUE(layersMayCollide(itemFor(BallKind::Bullet, 0), itemFor(BallKind::Pickup, 0)));
    EXPECT_TRUE(layersMayCollide(itemFor(BallKind::Plain, 0), itemFor(BallKind::Plain, 0)));
    EXPECT_TRUE(layersMayCollide(itemFor(BallKind::Ship, 0), itemFor(BallKind::Ship, 1)));
}

TEST(Task3LayersAndMasks, InTheLayersSceneEveryPairFollowsTheRules)
{
    LabSettings settings;
    settings.scene = Scene::Layers;
    ManyObjectsLevel level(settings);
    hitbox::simulate(level, 120); // a second: both ships have fired bullets
    const std::vector<Ball>& balls = level.getBalls();
    auto count = [&](BallKind kind)
    {
        return std::count_if(balls.begin(), balls.end(),
                             [&](const Ball& ball) { return ball.kind == kind; });
    };
    ASSERT_EQ(count(BallKind::Ship), 2);
    ASSERT_GT(count(BallKind::Bullet), 1);
    ASSERT_GT(count(BallKind::Pickup), 1);
    for (std::size_t i = 0; i < balls.size(); ++i)
        for (std::size_t j = i + 1; j < balls.size(); ++j)
        {
            const Ball& a = balls[i];
            const Ball& b = balls[j];
            auto are = [&](BallKind first, BallKind second) {
                return (a.kind == first && b.kind == second) ||
                       (a.kind == second && b.kind == first);
            };
            const bool ruledOut = are(BallKind::Pickup, BallKind::Pickup) ||
                                  are(BallKind::Bullet, BallKind::Bullet) ||
                                  (are(BallKind::Ship, BallKind::Bullet) && a.owner == b.owner);
            // ASSERT: the first pair that breaks a rule is enough.
            ASSERT_EQ(layersMayCollide(a.item(), b.item()), !ruledOut)
                << "balls " << i << " and " << j << " (kinds " << static_cast<int>(a.kind) << ", "
                << static_cast<int>(b.kind) << "; owners " << a.owner << ", " << b.owner << ")";
        }
}
