// The World: broadphase, then rules, then the exact test, then collisionResponse on both.
#include "support/SfmlPrinters.h"

#include "hitbox/objects/GameObject.h"
#include "hitbox/objects/World.h"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <memory>

using hitbox::BroadphaseMethod;
using hitbox::World;

namespace
{

// Remembers who it was told it hit.
class Recorder : public hitbox::GameObject
{
public:
    Recorder(float x, float y, float side = 20.f)
    {
        setSize({side, side});
        setPosition({x, y});
    }
    void collisionResponse(hitbox::GameObject* other) override { hits.push_back(other); }
    std::vector<hitbox::GameObject*> hits;
};

const BroadphaseMethod allMethods[] = {BroadphaseMethod::BruteForce, BroadphaseMethod::SortAndSweep,
                                       BroadphaseMethod::Grid, BroadphaseMethod::Quadtree};

TEST(World, CallsCollisionResponseOnBothObjectsOncePerPair)
{
    for (BroadphaseMethod method : allMethods)
    {
        Recorder a(0.f, 0.f), b(10.f, 10.f), c(200.f, 200.f);
        World world(method);
        world.add(a);
        world.add(b);
        world.add(c);
        EXPECT_EQ(world.checkCollisions(), 1u) << hitbox::toString(method);
        EXPECT_EQ(a.hits, std::vector<hitbox::GameObject*>{&b});
        EXPECT_EQ(b.hits, std::vector<hitbox::GameObject*>{&a});
        EXPECT_TRUE(c.hits.empty());
    }
}

TEST(World, UsesTheGridByDefaultAndALevelCanPickAnother)
{
    World world;
    EXPECT_EQ(world.getMethod(), BroadphaseMethod::Grid);
    world.setMethod(BroadphaseMethod::Quadtree);
    EXPECT_EQ(world.getMethod(), BroadphaseMethod::Quadtree);
}

// The grid's cell size as the World was given it, or the rule's (GridCellRule.h: here four
// 20 px boxes spread over 420 x 220 px, so sparse: 6 x their average side).
TEST(World, TakesTheGridsCellSizeAndKeepsItAcrossMethodChanges)
{
    Recorder a(0.f, 0.f), b(10.f, 10.f), c(200.f, 200.f), d(400.f, 90.f);
    World world;
    for (Recorder* object : {&a, &b, &c, &d})
        world.add(*object);
    ASSERT_EQ(world.checkCollisions(), 1u);
    EXPECT_FLOAT_EQ(world.getBroadphaseLayout().cellSize, 120.f) << "the rule: 6 x 20 px";

    hitbox::GridSettings grid;
    grid.cellSize = 100.f;
    world.setGridSettings(grid);
    EXPECT_EQ(world.checkCollisions(), 1u) << "the same pairs with any cell size";
    EXPECT_FLOAT_EQ(world.getBroadphaseLayout().cellSize, 100.f);
    world.setMethod(BroadphaseMethod::Quadtree);
    world.setMethod(BroadphaseMethod::Grid);
    EXPECT_EQ(world.checkCollisions(), 1u);
    EXPECT_FLOAT_EQ(world.getBroadphaseLayout().cellSize, 100.f) << "kept for the next grid";
    World moved(std::move(world));
    EXPECT_FLOAT_EQ(moved.getGridSettings().cellSize, 100.f);

    // Settings given while another method runs wait for the grid.
    World sweep(BroadphaseMethod::SortAndSweep);
    sweep.setGridSettings(grid);
    EXPECT_EQ(sweep.getMethod(), BroadphaseMethod::SortAndSweep);
    EXPECT_FLOAT_EQ(sweep.getGridSettings().cellSize, 100.f);

    // 0 and NaN: the rule again.
    for (float none : {0.f, std::numeric_limits<float>::quiet_NaN()})
    {
        grid.cellSize = none;
        moved.setGridSettings(grid);
        EXPECT_EQ(moved.checkCollisions(), 1u);
        EXPECT_FLOAT_EQ(moved.getBroadphaseLayout().cellSize, 120.f) << none;
    }
}

TEST(World, TouchingObjectsDoNotRespond)
{
    Recorder a(0.f, 0.f), b(20.f, 0.f);
    World world;
    world.add(a);
    world.add(b);
    EXPECT_EQ(world.checkCollisions(), 0u);
    EXPECT_TRUE(a.hits.empty());
}

TEST(World, SkipsDeadObjectsAndObjectsThatAreNotColliders)
{
    Recorder a(0.f, 0.f), dead(5.f, 5.f), ghost(8.f, 8.f);
    dead.setAlive(false);
    ghost.setCollider(false);
    World world;
    world.add(a);
    world.add(dead);
    world.add(ghost);
    EXPECT_EQ(world.checkCollisions(), 0u);
    EXPECT_TRUE(a.hits.empty());
    EXPECT_TRUE(dead.hits.empty());
    EXPECT_TRUE(ghost.hits.empty());
    dead.setAlive(true); // back in the game
    EXPECT_EQ(world.checkCollisions(), 1u);
}

TEST(World, HonoursLayersAndMasks)
{
    const std::uint32_t playerLayer = 1, bulletLayer = 2, enemyLayer = 4;
    Recorder player(0.f, 0.f), bullet(12.f, 12.f, 4.f), enemy(10.f, 10.f);
    World world;
    world.add(player, playerLayer, enemyLayer);
    world.add(bullet, bulletLayer, enemyLayer); // the player's bullet ignores the player
    world.add(enemy, enemyLayer, playerLayer | bulletLayer);
    EXPECT_EQ(world.checkCollisions(), 2u);
    EXPECT_EQ(player.hits, std::vector<hitbox::GameObject*>{&enemy});
    EXPECT_EQ(bullet.hits, std::vector<hitbox::GameObject*>{&enemy});
    EXPECT_EQ(enemy.hits, (std::vector<hitbox::GameObject*>{&player, &bullet}));
}

TEST(World, TheRuleCallbackVetoesPairsBeforeTheExactTest)
{
    Recorder a(0.f, 0.f), b(10.f, 10.f), c(5.f, 5.f);
    World world;
    world.add(a);
    world.add(b);
    world.add(c);
    int calls = 0;
    world.setRule(
        [&](const hitbox::GameObject& first, const hitbox::GameObject& second)
        {
            ++calls;
            return &first != &c && &second != &c; // c collides with nothing
        });
    EXPECT_EQ(world.checkCollisions(), 1u);
    EXPECT_EQ(calls, 3);                  // three overlapping pairs reached the rule
    EXPECT_EQ(world.getExactTests(), 1u); // only the allowed one got the exact test
    EXPECT_EQ(a.hits, std::vector<hitbox::GameObject*>{&b});
    EXPECT_TRUE(c.hits.empty());
}

TEST(World, CirclesUseTheExactCircleTestAfterTheBoxes)
{
    // The boxes' corners overlap, the inscribed circles do not: no response.
    Recorder a(0.f, 0.f), b(17.f, 17.f);
    World world;
    world.add(a, 1, 0xFFFFFFFF, World::Shape::Circle);
    world.add(b, 1, 0xFFFFFFFF, World::Shape::Circle);
    EXPECT_EQ(world.checkCollisions(), 0u);
    EXPECT_EQ(world.getBroadphaseStats().pairsFound, 1u);
    EXPECT_EQ(world.getExactTests(), 1u);
    b.setPosition({12.f, 0.f}); // centres 12 apart, radii 10 + 10
    EXPECT_EQ(world.checkCollisions(), 1u);
}

TEST(World, ACircleAgainstABoxUsesTheCircleBoxTest)
{
    Recorder circle(0.f, 0.f), box(18.f, 18.f);
    World world;
    world.add(circle, 1, 0xFFFFFFFF, World::Shape::Circle);
    world.add(box);
    EXPECT_EQ(world.checkCollisions(), 0u); // the circle misses the box's corner
    box.setPosition({15.f, 5.f});
    EXPECT_EQ(world.checkCollisions(), 1u);
    EXPECT_EQ(circle.hits, std::vector<hitbox::GameObject*>{&box});
}

TEST(World, RemovedObjectsNoLongerCollide)
{
    Recorder a(0.f, 0.f), b(10.f, 10.f);
    World world;
    world.add(a);
    world.add(b);
    world.add(b); // adding twice does not duplicate
    EXPECT_EQ(world.size(), 2u);
    world.remove(b);
    EXPECT_EQ(world.checkCollisions(), 0u);
    EXPECT_EQ(world.size(), 1u);
}

TEST(World, EveryMethodFindsTheSameCollisionsAmongManyObjects)
{
    std::vector<std::unique_ptr<Recorder>> objects;
    for (int i = 0; i < 400; ++i)
        objects.push_back(std::make_unique<Recorder>(static_cast<float>((i * 37) % 600),
                                                     static_cast<float>((i * 91) % 400)));
    std::vector<std::size_t> counts;
    for (BroadphaseMethod method : allMethods)
    {
        World world(method);
        for (auto& object : objects)
            world.add(*object);
        counts.push_back(world.checkCollisions());
    }
    EXPECT_GT(counts[0], 0u);
    for (std::size_t count : counts)
        EXPECT_EQ(count, counts[0]);
}

} // namespace
