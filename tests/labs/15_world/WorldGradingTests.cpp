// Grading tests of lab 15 (many objects in one World). Each suite is named after the task it
// checks; README.md lists them. The level runs with no window, one fixed step at a time.
//
// Each task's tests reach only that task's code: task 1's World has no rule and no player
// near anything, task 2's and task 3's scenes put every object on layer 1 with the mask
// "everything" (so task 1's layers play no part), task 2's has no rule and no enemies, task
// 3's no coins. A mistake in one task costs that task alone.
#include "labs/LabTesting.h"
#include "support/CollisionMatchers.h"
#include "support/SceneReplay.h"

#include "Pieces.h"
#include "Rules.h"
#include "WorldLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/objects/World.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

namespace
{

void runSteps(WorldLevel& level, int steps)
{
    hitbox::simulate(level, steps);
}

// A level with only the player (still, at `playerAt`, no autopilot) and what a test adds.
WorldLevel emptyLevel(sf::Vector2f playerAt)
{
    WorldLevel level;
    level.removeAllButThePlayer();
    level.placePlayer(playerAt);
    return level;
}

// Half the player's side and the coin's radius, whatever Pieces.h sets them to.
float playerHalf()
{
    return hitbox::toBox(Player({}).getCollisionBox()).width / 2.f;
}

float coinRadiusNow()
{
    return Coin({}).getBoundingCircle().radius;
}

const sf::Vector2f farCorner{100.f, 100.f};
const sf::Vector2f middle{600.f, 340.f};

// The test's own scene, stepped as WorldLevel::update steps the level (the player's blink
// runs down, one collision check, then the collected coins removed and counted), but with
// every object on layer 1 and mask "everything" and no game rule unless the test sets one.
struct Scene
{
    Scene() { world.add(player); }
    void addCoin(sf::Vector2f center)
    {
        coins.push_back(std::make_unique<Coin>(center));
        world.add(*coins.back(), 1, 0xFFFFFFFF, hitbox::World::Shape::Circle);
    }
    void addEnemy(sf::Vector2f center)
    {
        enemies.push_back(std::make_unique<Enemy>(center, sf::Vector2f{}));
        world.add(*enemies.back());
    }
    void step(int steps = 1)
    {
        for (int index = 0; index < steps; ++index)
        {
            player.update(hitbox::stepSeconds);
            world.checkCollisions();
            score += removeCollectedCoins(world, coins);
        }
    }

    hitbox::World world;
    Player player{middle};
    std::vector<std::unique_ptr<Coin>> coins;
    std::vector<std::unique_ptr<Enemy>> enemies;
    int score = 0;
};

} // namespace

TEST(Level, StartsWithCoinsEnemiesAndThePlayerInOneWorld)
{
    WorldLevel level;
    EXPECT_EQ(level.getCoinCount(), startCoins);
    EXPECT_EQ(level.getEnemyCount(), startEnemies);
    EXPECT_EQ(level.getWorld().size(), static_cast<std::size_t>(1 + startCoins + startEnemies));
}

TEST(Level, EveryBroadphaseMethodFindsTheSameCollisions)
{
    // M switches the method: the World finds the same pairs, only the work differs.
    std::vector<std::size_t> found;
    for (int method = 0; method < 4; ++method)
    {
        WorldLevel level(7);
        for (int press = 0; press < method; ++press)
        {
            hitbox::Input input;
            input.setKeyDown(sf::Keyboard::Key::M);
            level.handleInput(input, hitbox::stepSeconds);
        }
        EXPECT_EQ(static_cast<int>(level.getWorld().getMethod()), (2 + method) % 4);
        std::size_t collisions = 0;
        for (int step = 0; step < 600; ++step)
        {
            runSteps(level, 1);
            collisions += level.getWorld().getCollisions().size();
        }
        found.push_back(collisions);
    }
    for (std::size_t method = 1; method < found.size(); ++method)
        EXPECT_EQ(found[method], found[0]) << "method " << method;
}

// A coin that leaves the World from inside its own response, the moment the player takes it
// (the way many students write task 2 first). The World must finish the pass as if nothing
// moved: the player hears of the coin once, the two enemies of each other, and nobody of an
// object it never touched (issue 25: the next response used to go to the wrong object).
namespace
{
class CoinThatRemovesItself : public Coin
{
public:
    CoinThatRemovesItself(sf::Vector2f center, hitbox::World& world) : Coin(center), world(world) {}
    void collisionResponse(hitbox::GameObject* other) override
    {
        if (other != nullptr && kindOf(*other) == Kind::Player)
            world.remove(*this);
    }

private:
    hitbox::World& world;
};
} // namespace

TEST(Level, ACoinRemovedInsideItsResponseLeavesTheRestOfThePassIntact)
{
    for (int method = 0; method < 4; ++method)
    {
        hitbox::World world(static_cast<hitbox::BroadphaseMethod>(method));
        Player player(farCorner);
        CoinThatRemovesItself coin(farCorner, world);
        Enemy first(middle, {});
        Enemy second(middle + sf::Vector2f{5.f, 0.f}, {});
        world.add(player);
        world.add(coin, 1, 0xFFFFFFFF, hitbox::World::Shape::Circle);
        world.add(first);
        world.add(second);
        EXPECT_EQ(world.checkCollisions(), 2u) << "player-coin and enemy-enemy, method " << method;
        EXPECT_EQ(player.getHurtCount(), 0) << "the player never touched an enemy";
        EXPECT_EQ(first.getBumpCount(), 1);
        EXPECT_EQ(second.getBumpCount(), 1);
        EXPECT_EQ(world.size(), 3u) << "the coin left the World";
    }
}

TEST(Task1LayersAndMasks, CoinsNeverMeetCoinsOrEnemies)
{
    const Layers coin = layersFor(Kind::Coin);
    EXPECT_FALSE(mayEverMeet(coin, coin)) << "two coins never need an exact test";
    EXPECT_FALSE(mayEverMeet(coin, layersFor(Kind::Enemy))) << "enemies walk over coins";
    EXPECT_FALSE(mayEverMeet(layersFor(Kind::Enemy), coin));
}

TEST(Task1LayersAndMasks, ThePlayerMeetsCoinsAndEnemiesAndEnemiesBump)
{
    const Layers player = layersFor(Kind::Player);
    EXPECT_TRUE(mayEverMeet(player, layersFor(Kind::Coin)));
    EXPECT_TRUE(mayEverMeet(player, layersFor(Kind::Enemy)));
    EXPECT_TRUE(mayEverMeet(layersFor(Kind::Enemy), layersFor(Kind::Enemy)));
}

TEST(Task1LayersAndMasks, EachKindIsOnItsOwnLayer)
{
    EXPECT_EQ(layersFor(Kind::Player).layer, layer::player);
    EXPECT_EQ(layersFor(Kind::Coin).layer, layer::coin);
    EXPECT_EQ(layersFor(Kind::Enemy).layer, layer::enemy);
}

TEST(Task1LayersAndMasks, APileOfCoinsAndEnemiesCostsOnlyTheEnemyTests)
{
    // Four coins and three enemies on one spot, the player far away: 21 pairs overlap, but
    // only the 3 enemy-enemy pairs may ever meet, so only they get an exact test. Each object
    // is added with its layersFor, as WorldLevel adds it; no game rule is set.
    hitbox::World world;
    const auto add = [&world](hitbox::GameObject& object, Kind kind, hitbox::World::Shape shape)
    {
        const Layers layers = layersFor(kind);
        world.add(object, layers.layer, layers.mask, shape);
    };
    Player player(farCorner);
    add(player, Kind::Player, hitbox::World::Shape::Box);
    std::vector<std::unique_ptr<Coin>> coins;
    std::vector<std::unique_ptr<Enemy>> enemies;
    for (int coin = 0; coin < 4; ++coin)
    {
        coins.push_back(std::make_unique<Coin>(middle + sf::Vector2f{2.f * coin, 0.f}));
        add(*coins.back(), Kind::Coin, hitbox::World::Shape::Circle);
    }
    for (int enemy = 0; enemy < 3; ++enemy)
    {
        enemies.push_back(
            std::make_unique<Enemy>(middle + sf::Vector2f{0.f, 3.f * enemy}, sf::Vector2f{}));
        add(*enemies.back(), Kind::Enemy, hitbox::World::Shape::Box);
    }
    EXPECT_EQ(world.checkCollisions(), 3u);
    EXPECT_EQ(world.getExactTests(), 3u);
    EXPECT_EQ(enemies[0]->getBumpCount(), 2);
    world.clear();
}

TEST(Task1LayersAndMasks, TheLevelAddsEachObjectWithItsLayers)
{
    // The same pile in the level: WorldLevel adds every object with layersFor (and the
    // blinking rule, which no pair here needs).
    WorldLevel level = emptyLevel(farCorner);
    for (int coin = 0; coin < 4; ++coin)
        level.addCoin(middle + sf::Vector2f{2.f * coin, 0.f});
    runSteps(level, 1);
    EXPECT_EQ(level.getWorld().getExactTests(), 0u) << "coins never test against coins";
}

TEST(Task2CollectCoins, CoinTouchedByThePlayerIsCollected)
{
    Scene scene;
    scene.addCoin(middle + sf::Vector2f{playerHalf(), 0.f});
    const std::size_t before = scene.world.size();
    scene.step();
    EXPECT_EQ(scene.score, 1);
    EXPECT_EQ(scene.coins.size(), 0u);
    EXPECT_EQ(scene.world.size(), before - 1) << "a collected coin leaves the World";
}

TEST(Task2CollectCoins, EachCoinCountsOnce)
{
    Scene scene;
    scene.addCoin(middle);
    scene.addCoin(middle + sf::Vector2f{5.f, 0.f});
    scene.addCoin(middle + sf::Vector2f{0.f, -5.f});
    scene.addCoin(middle + sf::Vector2f{300.f, 0.f}); // out of reach
    scene.step(10);
    EXPECT_EQ(scene.score, 3);
    EXPECT_EQ(scene.coins.size(), 1u);
    EXPECT_EQ(scene.world.size(), 2u);
}

// The program's own scene (`lab15_world --seed 3`: coins, enemies, new waves), played by
// scripted arrow keys, checked at every step: the score rises by exactly the coins that left.
// A failure prints the command that opens the run in the window at the failing step.
TEST(Task2CollectCoins, InTheProgramsSceneEveryCoinThatLeavesScoresOnce)
{
    const unsigned seed = 3;
    WorldLevel level(seed);
    scenereplay::RecordedScene scene(level, {"Lab 15 - Many objects in one World", seed});
    const sf::Keyboard::Key arrows[] = {sf::Keyboard::Key::Left, sf::Keyboard::Key::Right,
                                        sf::Keyboard::Key::Up, sf::Keyboard::Key::Down};
    std::mt19937 random(11);
    std::uniform_int_distribution<int> pick(0, 4); // 4: let go (the autopilot stays off)
    hitbox::Input input;
    // 40 s of play, a new arrow (or none) every quarter of a second.
    const int stepsPerSecond = static_cast<int>(hitbox::stepsPerSecond);
    for (int i = 0; i < stepsPerSecond * 40; ++i)
    {
        if (i % (stepsPerSecond / 4) == 0)
        {
            for (sf::Keyboard::Key arrow : arrows)
                input.setKeyUp(arrow);
            const int chosen = pick(random);
            if (chosen < 4)
                input.setKeyDown(arrows[chosen]);
        }
        const int scoreBefore = level.getScore();
        const int coinsBefore = level.getCoinCount();
        scene.step(input);
        const bool newWave = level.getCoinCount() > coinsBefore;
        const int coinsLeft = coinsBefore - level.getCoinCount() + (newWave ? startCoins : 0);
        ASSERT_EQ(level.getScore() - scoreBefore, coinsLeft)
            << "step " << scene.stepCount() - 1 << ": the score rose by "
            << level.getScore() - scoreBefore << " while " << coinsLeft << " coin(s) left"
            << scene.replayCommand();
    }
    // No "some coins were collected" check here: whether the player meets coins at all is task
    // 1's layers and task 3's rule, and a mistake there must cost only its own task. The
    // tests above show that collecting works; this one checks the count in the real scene.
}

TEST(Task2CollectCoins, CoinOnlyTouchingThePlayerStays)
{
    // The edge rule: touching is not colliding. The coin's circle touches the player's
    // right side, and the two never overlap.
    Scene scene;
    scene.addCoin(middle + sf::Vector2f{playerHalf() + coinRadiusNow(), 0.f});
    EXPECT_THAT(*scene.coins[0],
                hitbox::testing::NotCollides(scene.player, hitbox::World::Shape::Circle));
    scene.step(10);
    EXPECT_EQ(scene.score, 0);
    EXPECT_EQ(scene.coins.size(), 1u);
}

TEST(Task2CollectCoins, OnlyThePlayerCollects)
{
    Coin coin(middle);
    Enemy enemy(middle, {});
    coin.collisionResponse(&enemy);
    coin.collisionResponse(nullptr);
    EXPECT_FALSE(coin.isCollected()) << "an enemy or a wall does not collect a coin";
    Player player(middle);
    coin.collisionResponse(&player);
    EXPECT_TRUE(coin.isCollected());
}

TEST(Task2CollectCoins, ACollectedCoinIsSkippedForTheRestOfTheCheck)
{
    // Collected means dead at once (setAlive(false)): the World skips it for the rest of this
    // checkCollisions, so a second player touching it in the same check finds nothing there.
    Coin coin(middle);
    ASSERT_TRUE(coin.isAlive());
    Player player(middle);
    coin.collisionResponse(&player);
    EXPECT_FALSE(coin.isAlive()) << "a collected coin should be set dead (setAlive(false))";
}

namespace
{
// A coin that, when destroyed, notes whether it was still in `world` (its own destructor runs
// before GameObject's, which is where the World's safety net takes it out).
class CoinThatWatchesItsEnd : public Coin
{
public:
    CoinThatWatchesItsEnd(sf::Vector2f center, const hitbox::World& world, int& destroyedInWorld)
        : Coin(center), world(world), destroyedInWorld(destroyedInWorld)
    {
    }
    ~CoinThatWatchesItsEnd() override
    {
        if (world.contains(*this))
            ++destroyedInWorld;
    }
    CoinThatWatchesItsEnd(const CoinThatWatchesItsEnd&) = delete;
    CoinThatWatchesItsEnd& operator=(const CoinThatWatchesItsEnd&) = delete;

private:
    const hitbox::World& world;
    int& destroyedInWorld;
};
} // namespace

TEST(Task2CollectCoins, CollectedCoinsLeaveTheWorldBeforeTheyAreDestroyed)
{
    // The sheet's order: the World keeps pointers to objects it does not own, so a coin is
    // taken out of it first, then destroyed. (Hitbox's World would take a destroyed coin out
    // by itself, so only the coin can tell: it notes whether it was still in the World.)
    hitbox::World world;
    int destroyedInWorld = 0;
    std::vector<std::unique_ptr<Coin>> coins;
    Player player(farCorner);
    world.add(player);
    for (int coin = 0; coin < 3; ++coin)
    {
        coins.push_back(std::make_unique<CoinThatWatchesItsEnd>(
            middle + sf::Vector2f{100.f * coin, 0.f}, world, destroyedInWorld));
        world.add(*coins.back(), 1, 0xFFFFFFFF, hitbox::World::Shape::Circle);
    }
    const Coin* kept = coins[1].get();
    coins[0]->collisionResponse(&player);
    coins[2]->collisionResponse(&player);
    EXPECT_EQ(removeCollectedCoins(world, coins), 2);
    EXPECT_EQ(destroyedInWorld, 0) << "a collected coin was destroyed while still in the World: "
                                      "world.remove(*coin) first, then erase it";
    ASSERT_EQ(coins.size(), 1u);
    EXPECT_EQ(coins[0].get(), kept);
    EXPECT_EQ(world.size(), 2u);
    world.checkCollisions();
    EXPECT_EQ(removeCollectedCoins(world, coins), 0);
}

TEST(Task3BlinkingPlayerRule, ABlinkingPlayerIsNotTestedAgainstEnemies)
{
    Player player(middle);
    Enemy enemy(middle, {});
    player.collisionResponse(&enemy);
    ASSERT_TRUE(player.isBlinking());
    EXPECT_FALSE(mayMeetNow(player, enemy));
    EXPECT_FALSE(mayMeetNow(enemy, player)) << "the World may hand the pair either way round";
}

TEST(Task3BlinkingPlayerRule, EveryOtherPairIsStillTested)
{
    Player player(middle);
    Enemy enemy(middle, {});
    Enemy other(middle, {});
    Coin coin(middle);
    EXPECT_TRUE(mayMeetNow(player, enemy)) << "a player who is not blinking can be hurt";
    player.collisionResponse(&enemy);
    EXPECT_TRUE(mayMeetNow(player, coin)) << "a blinking player still collects coins";
    EXPECT_TRUE(mayMeetNow(coin, player));
    EXPECT_TRUE(mayMeetNow(enemy, other)) << "enemies still bump each other";
}

TEST(Task3BlinkingPlayerRule, PlayerStandingOnAnEnemyIsHurtOncePerBlink)
{
    Scene scene;
    scene.world.setRule(mayMeetNow);
    scene.addEnemy(middle + sf::Vector2f{10.f, 0.f});
    scene.step();
    EXPECT_EQ(scene.player.getHurtCount(), 1);
    scene.step();
    EXPECT_EQ(scene.world.getExactTests(), 0u) << "the blinking pair needs no exact test";
    const int blinkSteps = static_cast<int>(blinkSeconds * hitbox::stepsPerSecond);
    scene.step(blinkSteps - 10);
    EXPECT_EQ(scene.player.getHurtCount(), 1) << "hurt again while still blinking";
    scene.step(20);
    EXPECT_EQ(scene.player.getHurtCount(), 2) << "the blink is over: the enemy hurts again";
}

TEST(Task3BlinkingPlayerRule, TheLevelUsesTheRule)
{
    // In the level (which adds the rule with world.setRule): the blinking player and the
    // enemy it stands on cost no exact test.
    WorldLevel level = emptyLevel(middle);
    level.addEnemy(middle + sf::Vector2f{10.f, 0.f}, {});
    runSteps(level, 2);
    EXPECT_EQ(level.getWorld().getExactTests(), 0u) << "the blinking pair needs no exact test";
}
