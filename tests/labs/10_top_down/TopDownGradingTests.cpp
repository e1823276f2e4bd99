// Grading tests of lab 10 (top-down). Suites named TaskN... check task N of README.md; the
// others check what the lab gives you ready-made (hitbox vs sprite, the sword, depth
// sorting). The level runs with no window: scripted keys, fixed steps of 1/120 s.
#include "TopDownLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/debug/DebugRenderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

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
    hitbox::Input input;
};

// Where `actor` ends up after `seconds` of walking right at `speed` px/s, moved by the level's
// moveAndSlide alone (no input, no enemy state, no hits), one fixed step at a time.
Actor afterWalkingRight(const TopDownLevel& level, Actor actor, float speed, float seconds)
{
    for (int step = 0; step < static_cast<int>(seconds * hitbox::stepsPerSecond + 0.5f); ++step)
        level.moveAndSlide(actor, {speed * hitbox::stepSeconds, 0.f});
    return actor;
}
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

TEST(Task1PerAxis, FromEachSideAMoveIntoAWallEndsFlushAgainstIt)
{
    // The wall 600..640 x 200..500. From each side, 5 px away (and 0.25 px away with a tiny
    // move), a move 10 px (0.5 px) into it ends with the feet touching that side.
    Game game;
    const hitbox::Box wall{600.f, 200.f, 40.f, 300.f};
    game.level.addWall(wall);
    game.level.placePlayer({500.f, 350.f});
    const Actor start = game.level.getPlayer();
    const hitbox::Vec2 half = start.hitboxSize / 2.f;
    struct Case
    {
        hitbox::Vec2 feet;
        hitbox::Vec2 direction;
        const char* side;
    };
    const Case cases[] = {{{wall.left - half.x, 350.f}, {1.f, 0.f}, "left"},
                          {{wall.left + wall.width + half.x, 350.f}, {-1.f, 0.f}, "right"},
                          {{620.f, wall.top - half.y}, {0.f, 1.f}, "top"},
                          {{620.f, wall.top + wall.height + half.y}, {0.f, -1.f}, "bottom"}};
    for (const Case& c : cases)
        for (const float distance : {5.f, 0.25f})
        {
            Actor actor = start;
            actor.feet = c.feet - c.direction * distance;
            game.level.moveAndSlide(actor, c.direction * (2.f * distance));
            EXPECT_FLOAT_EQ(actor.feet.x, c.feet.x)
                << "moving into the wall's " << c.side << " side";
            EXPECT_FLOAT_EQ(actor.feet.y, c.feet.y)
                << "moving into the wall's " << c.side << " side";
        }
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
    const Actor slime = afterWalkingRight(game.level, game.level.getEnemies().at(0).body,
                                          TopDownLevel::enemySpeed, 1.f);
    EXPECT_FLOAT_EQ(slime.hitbox().left + slime.hitbox().width, 480.f);
}

TEST(Task1PerAxis, KnockbackSpeedStopsAtAWallToo)
{
    // A knocked-back actor moves fastest of all, through moveAndSlide like any other move.
    Game game;
    game.level.addWall({560.f, 200.f, 40.f, 200.f});
    game.level.placePlayer({500.f, 300.f});
    const Actor actor =
        afterWalkingRight(game.level, game.player(), TopDownLevel::knockbackSpeed, 0.25f);
    EXPECT_FLOAT_EQ(actor.hitbox().left + actor.hitbox().width, 560.f);
}

TEST(Task1PerAxis, FeetTouchingAWallSlideAlongItFreely)
{
    // The edge rule: touching is not overlapping. Feet flush against a wall's side walk
    // along it without being pushed anywhere, and can walk away from it.
    Game game;
    game.level.addWall({600.f, 200.f, 40.f, 300.f});
    game.level.placePlayer({500.f, 350.f});
    Actor actor = game.level.getPlayer();
    actor.feet.x = 600.f - actor.hitboxSize.x / 2.f; // right edge exactly on the wall
    game.level.moveAndSlide(actor, {0.f, 20.f});
    EXPECT_FLOAT_EQ(actor.feet.y, 370.f) << "moved along the wall";
    EXPECT_FLOAT_EQ(actor.hitbox().left + actor.hitbox().width, 600.f) << "still flush";
    game.level.moveAndSlide(actor, {0.f, -40.f});
    EXPECT_FLOAT_EQ(actor.feet.y, 330.f) << "and back up";
    game.level.moveAndSlide(actor, {-10.f, 0.f});
    EXPECT_FLOAT_EQ(actor.hitbox().left + actor.hitbox().width, 590.f) << "and away from it";
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

TEST(Task2Radii, EveryFrameEachEnemyChoosesByItsDistanceToThePlayer)
{
    // One frame: each slime's state is chosen before anything moves or is hurt, so this
    // checks task 2 alone.
    Game game;
    game.level.placePlayer({600.f, 300.f});
    game.level.addEnemy({600.f - TopDownLevel::attackRadius + 10.f, 300.f}); // attack
    game.level.addEnemy({600.f + TopDownLevel::noticeRadius - 10.f, 300.f}); // chase
    game.level.addEnemy({600.f, 300.f + TopDownLevel::noticeRadius + 10.f}); // idle
    game.frame();
    const std::vector<Enemy>& enemies = game.level.getEnemies();
    ASSERT_EQ(enemies.size(), 3u);
    // The room is empty, but whether an enemy sees across it is task 4's canSee: an enemy that
    // does not see the player stays idle whatever task 2 chose, so a wrong canSee costs task 4
    // alone.
    const EnemyState wanted[] = {EnemyState::Attack, EnemyState::Chase, EnemyState::Idle};
    for (std::size_t index = 0; index < enemies.size(); ++index)
    {
        const bool seen =
            canSee(game.level.getSight(), enemies[index].body.feet, game.player().feet);
        EXPECT_EQ(enemies[index].state, seen ? wanted[index] : EnemyState::Idle)
            << "enemy " << index;
    }
}

TEST(Task2Radii, AChasingEnemyWalksTowardsThePlayer)
{
    // Walking is task 1's moveAndSlide: the enemy must end where moveAndSlide takes it at
    // enemySpeed towards the player (straight right here), whatever moveAndSlide does, so a
    // mistake in task 1 costs task 1 alone.
    // Seeing the player across the empty room is task 4's canSee: the expected walk takes a
    // step only on the frames canSee sees, so a wrong canSee costs task 4 alone.
    Game game;
    game.level.addEnemy({300.f, 300.f});
    game.level.placePlayer({500.f, 300.f});
    Actor expected = game.level.getEnemies().at(0).body;
    bool seen = false;
    for (int step = 0; step < static_cast<int>(0.25f * hitbox::stepsPerSecond + 0.5f); ++step)
    {
        seen = canSee(game.level.getSight(), expected.feet, game.player().feet);
        const float speed = seen ? TopDownLevel::enemySpeed : 0.f;
        game.level.moveAndSlide(expected, {speed * hitbox::stepSeconds, 0.f});
    }
    // 32 px at 130 px/s: still inside the notice radius and outside the attack radius, even
    // if moveAndSlide took it the wrong way.
    game.run(0.25f);
    const Enemy& enemy = game.level.getEnemies().at(0);
    EXPECT_EQ(enemy.state, seen ? EnemyState::Chase : EnemyState::Idle);
    EXPECT_NEAR(enemy.body.feet.x, expected.feet.x, 1e-3f)
        << "walked at enemySpeed towards the player";
    EXPECT_FLOAT_EQ(enemy.body.feet.y, expected.feet.y);
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

TEST(Task3Knockback, TheHitStartsTheGivenInvulnerableTimeAtFullSpeed)
{
    Actor victim;
    victim.feet = {100.f, 100.f};
    victim.health = 3;
    EXPECT_TRUE(TopDownLevel::hurt(victim, {70.f, 60.f}, 0.4f)); // from up and to the left
    EXPECT_FLOAT_EQ(victim.invulnerable, 0.4f);
    EXPECT_NEAR(std::hypot(victim.knockback.x, victim.knockback.y), TopDownLevel::knockbackSpeed,
                0.01f);
    EXPECT_NEAR(victim.knockback.x / victim.knockback.y, 30.f / 40.f, 1e-4f) << "straight away";
}

TEST(Task3Knockback, InvulnerableTimeRunOutExactlyLetsTheNextHitCount)
{
    // The edge of the rule: "while invulnerable > 0". At exactly 0 the hit counts; a
    // moment before, it does not.
    Actor victim;
    victim.health = 3;
    victim.invulnerable = 0.001f;
    EXPECT_FALSE(TopDownLevel::hurt(victim, {0.f, 50.f}, 1.f));
    EXPECT_EQ(victim.health, 3);
    victim.invulnerable = 0.f;
    EXPECT_TRUE(TopDownLevel::hurt(victim, {0.f, 50.f}, 1.f));
    EXPECT_EQ(victim.health, 2);
}

TEST(Task3Knockback, ASwordHitThrowsTheSlimeBackAndItBlinks)
{
    // The player's sword hurts the slime (no slime has to attack: task 2 is not needed).
    Game game;
    game.level.addEnemy({560.f, 300.f});
    game.level.placePlayer({500.f, 300.f});
    game.tap(sf::Keyboard::Key::D); // face right
    game.tap(sf::Keyboard::Key::Space);
    // The push, not where it ends: moving the slime by it is task 1's moveAndSlide.
    const hitbox::Vec2 push = game.level.getEnemies().at(0).body.knockback;
    EXPECT_GT(push.x, TopDownLevel::knockbackSpeed / 2.f) << "knocked back, away from the player";
    EXPECT_NEAR(push.y, 0.f, 1e-3f) << "straight away from the player";
    bool blinkedOut = false;
    bool shown = false;
    for (int frame = 0; frame < 23; ++frame) // the knockback's 0.2 s
    {
        game.frame();
        const Actor& slime = game.level.getEnemies().at(0).body;
        (TopDownLevel::isBlinkedOut(slime) ? blinkedOut : shown) = true;
    }
    const Actor& slime = game.level.getEnemies().at(0).body;
    EXPECT_TRUE(blinkedOut && shown) << "blinks while invulnerable";
    EXPECT_GT(slime.invulnerable, 0.f);
    EXPECT_EQ(slime.health, TopDownLevel::enemyHealth - 1);
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
