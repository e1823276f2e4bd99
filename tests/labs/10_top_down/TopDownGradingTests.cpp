// Grading tests of lab 10 (top-down). Suites named TaskN... check task N of README.md; the
// others check what the lab gives you ready-made (hitbox vs sprite, the sword, depth
// sorting). The level runs with no window: scripted keys, fixed steps of 1/120 s.
#include "TopDownLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
struct Game
{
    // An empty room (only the outer walls) unless the test adds things.
    Game() { level.clearScene(); }

    void frame()
    {
        level.handleInput(input, hitbox::stepSeconds);
        level.update(hitbox::stepSeconds);
        input.update();
    }
    void run(float seconds)
    {
        for (int index = 0; index < static_cast<int>(seconds * hitbox::stepsPerSecond + 0.5f);
             ++index)
            frame();
    }
    void tap(sf::Keyboard::Key key)
    {
        input.setKeyDown(key);
        frame();
        input.setKeyUp(key);
    }
    const Actor& player() const { return level.getPlayer(); }

    TopDownLevel level;
    Input input;
};
} // namespace

// ---- Task 1: per-axis move-then-resolve ------------------------------------------------------

TEST(Task1PerAxis, WalkingIntoAWallStopsTheFeetFlushAgainstIt)
{
    Game game;
    game.level.addWall({600.f, 200.f, 40.f, 300.f});
    game.level.placePlayer({500.f, 350.f});
    game.input.setKeyDown(sf::Keyboard::Key::D);
    game.run(1.f);
    const hitbox::Box feet = game.player().hitbox();
    EXPECT_FLOAT_EQ(feet.left + feet.width, 600.f);
}

TEST(Task1PerAxis, WalkingDiagonallyIntoAWallSlidesAlongIt)
{
    Game game;
    game.level.addWall({300.f, 200.f, 600.f, 40.f}); // a wall above the player
    game.level.placePlayer({400.f, 270.f});
    game.input.setKeyDown(sf::Keyboard::Key::W);
    game.input.setKeyDown(sf::Keyboard::Key::D);
    game.run(0.5f);
    const hitbox::Box feet = game.player().hitbox();
    EXPECT_FLOAT_EQ(feet.top, 240.f) << "stopped by the wall on y";
    // The x part of the diagonal keeps going: 240 / sqrt(2) px/s for half a second.
    EXPECT_NEAR(game.player().feet.x, 400.f + TopDownLevel::playerSpeed / std::sqrt(2.f) * 0.5f,
                1.f);
}

TEST(Task1PerAxis, EnemiesAreStoppedByWallsToo)
{
    Game game;
    game.level.addWall({480.f, 100.f, 40.f, 400.f});
    game.level.addEnemy({400.f, 300.f});
    game.level.placePlayer({600.f, 300.f}); // behind the wall, inside the notice radius
    game.run(2.f);
    const hitbox::Box feet = game.level.getEnemies().at(0).body.hitbox();
    EXPECT_LE(feet.left + feet.width, 480.f);
}

TEST(Task1PerAxis, ATreeTrunkBlocksButTheLeavesDoNot)
{
    Game game;
    game.level.addTree({600.f, 300.f});
    const hitbox::Box trunk = game.level.getTrees().at(0).hitbox();
    // Walk up from below: stopped by the small trunk box, deep inside the tree's picture.
    game.level.placePlayer({600.f, 420.f});
    game.input.setKeyDown(sf::Keyboard::Key::W);
    game.run(1.f);
    EXPECT_FLOAT_EQ(game.player().hitbox().top, trunk.top + trunk.height);
    // Beside the trunk, walking up: nothing stops the player behind the leaves.
    game.level.placePlayer({650.f, 420.f});
    game.run(1.f);
    EXPECT_LT(game.player().feet.y, trunk.top - 50.f);
}

// ---- Task 2: notice and attack radii ---------------------------------------------------------

TEST(Task2Radii, FarAwayTheEnemyStaysIdle)
{
    EXPECT_EQ(TopDownLevel::chooseEnemyState({0.f, 0.f}, {400.f, 0.f}), EnemyState::Idle);
}

TEST(Task2Radii, InsideTheNoticeRadiusTheEnemyChases)
{
    EXPECT_EQ(TopDownLevel::chooseEnemyState({0.f, 0.f}, {150.f, 150.f}), EnemyState::Chase);
}

TEST(Task2Radii, InsideTheAttackRadiusTheEnemyAttacks)
{
    EXPECT_EQ(TopDownLevel::chooseEnemyState({100.f, 100.f}, {130.f, 130.f}), EnemyState::Attack);
}

TEST(Task2Radii, ExactlyOnACircleCountsAsOutside)
{
    // The edge rule: touching is not inside.
    EXPECT_EQ(TopDownLevel::chooseEnemyState({0.f, 0.f}, {TopDownLevel::noticeRadius, 0.f}),
              EnemyState::Idle);
    EXPECT_EQ(TopDownLevel::chooseEnemyState({0.f, 0.f}, {0.f, TopDownLevel::attackRadius}),
              EnemyState::Chase);
}

TEST(Task2Radii, ANoticingEnemyWalksUpToThePlayerAndStrikes)
{
    Game game;
    game.level.addEnemy({300.f, 300.f});
    game.level.placePlayer({500.f, 300.f});
    int frames = 0;
    while (game.player().health == TopDownLevel::playerHealth && frames < 360)
    {
        game.frame();
        ++frames;
    }
    const Enemy& enemy = game.level.getEnemies().at(0);
    EXPECT_EQ(game.player().health, TopDownLevel::playerHealth - 1) << "struck once";
    EXPECT_EQ(enemy.state, EnemyState::Attack);
    EXPECT_GT(enemy.body.feet.x, 300.f + 100.f) << "walked towards the player";
    // (200 - 56) px at 130 px/s: about 1.1 s, and no more.
    EXPECT_LT(frames, 150);
}

TEST(Task2Radii, AnEnemyThatHasNotNoticedDoesNotMove)
{
    Game game;
    game.level.addEnemy({200.f, 300.f});
    game.level.placePlayer({900.f, 300.f});
    game.run(2.f);
    EXPECT_EQ(game.level.getEnemies().at(0).body.feet, hitbox::Vec2(200.f, 300.f));
}

// ---- Task 3: knockback and invulnerability ---------------------------------------------------

TEST(Task3Knockback, AHitPushesTheVictimAwayFromTheHitter)
{
    Actor victim;
    victim.feet = {100.f, 100.f};
    victim.health = 3;
    EXPECT_TRUE(TopDownLevel::hurt(victim, {100.f, 150.f}, 1.f));
    EXPECT_EQ(victim.health, 2);
    EXPECT_FLOAT_EQ(victim.knockback.y, -TopDownLevel::knockbackSpeed) << "pushed up, away";
    EXPECT_FLOAT_EQ(victim.knockback.x, 0.f);
}

TEST(Task3Knockback, ASecondHitWhileInvulnerableDoesNothing)
{
    Actor victim;
    victim.health = 3;
    TopDownLevel::hurt(victim, {0.f, 50.f}, 1.f);
    EXPECT_FALSE(TopDownLevel::hurt(victim, {0.f, 50.f}, 1.f));
    EXPECT_EQ(victim.health, 2);
}

TEST(Task3Knockback, AnEnemyNextToThePlayerTakesOneLifePerSecondAtMost)
{
    Game game;
    game.level.addEnemy({500.f, 300.f});
    game.level.placePlayer({540.f, 300.f}); // inside the attack radius
    game.run(0.95f);                        // two attack intervals, but one invulnerability time
    EXPECT_EQ(game.player().health, TopDownLevel::playerHealth - 1);
}

TEST(Task3Knockback, TheHitPlayerIsThrownBackAndBlinks)
{
    Game game;
    game.level.addEnemy({500.f, 300.f});
    game.level.placePlayer({540.f, 300.f});
    game.frame();
    bool blinkedOut = false;
    bool shown = false;
    for (int frame = 0; frame < 60; ++frame)
    {
        game.frame();
        (TopDownLevel::isBlinkedOut(game.player()) ? blinkedOut : shown) = true;
    }
    EXPECT_GT(game.player().feet.x, 540.f + 50.f) << "knocked back, away from the enemy";
    EXPECT_TRUE(blinkedOut && shown) << "blinks while invulnerable";
    EXPECT_GT(game.player().invulnerable, 0.f);
}

TEST(Task3Knockback, KnockbackDoesNotPushThroughAWall)
{
    Game game;
    game.level.addWall({560.f, 200.f, 40.f, 200.f});
    game.level.addEnemy({500.f, 300.f});
    game.level.placePlayer({540.f, 300.f});
    game.run(0.5f);
    EXPECT_LE(game.player().hitbox().left + game.player().hitbox().width, 560.f);
}

// ---- Ready-made: the sword, the hitbox, drawing order ----------------------------------------

TEST(Sword, ASwingHitsTheEnemyInFrontAndThreeHitsDefeatIt)
{
    Game game;
    game.level.addEnemy({560.f, 300.f});
    game.level.placePlayer({500.f, 300.f});
    game.tap(sf::Keyboard::Key::D); // face right
    game.tap(sf::Keyboard::Key::Space);
    ASSERT_EQ(game.level.getEnemies().size(), 1u);
    EXPECT_EQ(game.level.getEnemies()[0].body.health, TopDownLevel::enemyHealth - 1);
    for (int swing = 0; swing < 6 && !game.level.getEnemies().empty(); ++swing)
    {
        game.level.placePlayer({game.level.getEnemies()[0].body.feet.x - 60.f, 300.f});
        game.tap(sf::Keyboard::Key::Space);
        game.run(0.5f);
    }
    EXPECT_TRUE(game.level.getEnemies().empty());
}

TEST(Hitbox, TheFeetBoxIsSmallerThanTheSpriteAndAtItsBottom)
{
    Game game;
    game.level.placePlayer({400.f, 300.f});
    const hitbox::Box feet = game.player().hitbox();
    const hitbox::Box sprite = game.player().spriteBox();
    EXPECT_LT(feet.width * feet.height, sprite.width * sprite.height / 4.f);
    EXPECT_FLOAT_EQ(feet.top + feet.height, sprite.top + sprite.height);
    EXPECT_GE(feet.left, sprite.left);
    EXPECT_LE(feet.left + feet.width, sprite.left + sprite.width);
}

TEST(DepthSort, WhoeverIsFurtherDownIsDrawnLater)
{
    Game game;
    game.level.addTree({400.f, 300.f});
    game.level.placePlayer({420.f, 280.f}); // behind the tree
    std::vector<DrawItem> order = game.level.drawOrder();
    ASSERT_EQ(order.size(), 2u);
    EXPECT_EQ(order[0].kind, DrawItem::Player) << "behind the tree: drawn first, covered";
    EXPECT_EQ(order[1].kind, DrawItem::Tree);

    game.level.placePlayer({420.f, 330.f}); // in front of the tree
    order = game.level.drawOrder();
    EXPECT_EQ(order[0].kind, DrawItem::Tree);
    EXPECT_EQ(order[1].kind, DrawItem::Player);
}

TEST(DebugView, ShowsHitboxesSpritesAndCircles)
{
    TopDownLevel level; // the lab's own scene
    hitbox::DebugRenderer debug;
    level.renderDebug(debug);
    EXPECT_GT(debug.getVertices().getVertexCount(), 500u);
}
