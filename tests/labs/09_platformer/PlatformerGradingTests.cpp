// Grading tests of lab 9 (platformer). Suites named TaskN... check task N of README.md; the
// others check what the lab gives you ready-made (movement, the fixed step, the debug view).
// Every test runs the level with no window: scripted keys, fixed steps.
#include "PlatformerTestSupport.h"

#include "hitbox/debug/DebugRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using platformertest::Game;

namespace
{
// The highest point (smallest y) the player's box reaches in `seconds`.
float highestTop(Game& game, float seconds)
{
    float top = game.position().y;
    for (int frame = 0; frame < static_cast<int>(seconds * hitbox::stepsPerSecond); ++frame)
    {
        game.frame();
        top = std::min(top, game.position().y);
    }
    return top;
}
} // namespace

// ---- Task 1: gravity, and a jump only from the ground -------------------------------------
// Task 1's tests switch task 4's speed cap off: the speeds they reach stay under it anyway (a
// jump is 1140 px/s, the cap 2250), so a mistake in task 4 costs task 4 alone.

TEST(Task1Gravity, PlayerFallsAndComesToRestOnTheFloor)
{
    Game game(platformertest::room);
    game.level.setSpeedCap(false);
    game.run(1.f);
    EXPECT_NEAR(game.feet(), platformertest::roomFloorTop, 0.01f);
    EXPECT_TRUE(game.level.isGrounded());
    EXPECT_EQ(game.velocity().y, 0.f) << "standing still, gravity must not build up speed";
}

TEST(Task1Gravity, FallingSpeedGrowsByGravityEachStep)
{
    Game game(platformertest::deepShaft(40));
    game.level.setSpeedCap(false);
    game.frame();
    const float first = game.velocity().y;
    game.frame();
    EXPECT_NEAR(first, Player::gravity * hitbox::stepSeconds, 0.01f);
    EXPECT_NEAR(game.velocity().y - first, Player::gravity * hitbox::stepSeconds, 0.01f);
}

TEST(Task1Jump, JumpFromTheFloorRisesAboutFourTiles)
{
    Game game(platformertest::room);
    game.level.setSpeedCap(false);
    game.run(1.f);
    const float standingTop = game.position().y;
    game.tap(sf::Keyboard::Key::Space);
    const float top = highestTop(game, 1.f);
    // v^2 / 2g = 1140^2 / 6600 = 197 pixels, give or take one step.
    const float expected = Player::jumpSpeed * Player::jumpSpeed / (2.f * Player::gravity);
    EXPECT_NEAR(standingTop - top, expected, 10.f);
    EXPECT_NEAR(game.feet(), platformertest::roomFloorTop, 0.01f) << "lands again";
}

TEST(Task1Jump, JumpPressedInTheAirDoesNothing)
{
    Game game(platformertest::deepShaft(40));
    game.level.setSpeedCap(false);
    game.frame(); // falling from the start
    game.tap(sf::Keyboard::Key::Space);
    EXPECT_GT(game.velocity().y, 0.f) << "still falling: no jumping off thin air";
}

TEST(Task1Jump, NoSecondJumpAtTheTopOfTheFirst)
{
    Game single(platformertest::room);
    single.level.setSpeedCap(false);
    single.run(1.f);
    single.tap(sf::Keyboard::Key::Space);
    const float singleTop = highestTop(single, 1.f);

    Game twice(platformertest::room);

    twice.level.setSpeedCap(false);
    twice.run(1.f);
    twice.tap(sf::Keyboard::Key::Space);
    twice.run(0.25f);
    twice.tap(sf::Keyboard::Key::Space);
    EXPECT_FLOAT_EQ(highestTop(twice, 1.f), singleTop);
}

// ---- Task 2: corners resolve along the axis of least penetration ----------------------------

TEST(Task2LeastPenetration, CornerDeepSidewaysShallowDownIsPushedUp)
{
    const CollisionPoint& rightBottom = PlatformerLevel::collisionPoints[7];
    const hitbox::Box tile{64.f, 64.f, 32.f, 32.f};
    const hitbox::Contact push = PlatformerLevel::pushOut(rightBottom, {74.f, 67.f}, tile);
    ASSERT_TRUE(push.hit);
    EXPECT_EQ(push.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(push.depth, 3.f);
}

TEST(Task2LeastPenetration, CornerShallowSidewaysDeepDownIsPushedSideways)
{
    const CollisionPoint& leftTop = PlatformerLevel::collisionPoints[4];
    const hitbox::Box tile{64.f, 64.f, 32.f, 32.f};
    const hitbox::Contact push = PlatformerLevel::pushOut(leftTop, {93.f, 80.f}, tile);
    ASSERT_TRUE(push.hit);
    EXPECT_EQ(push.normal, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(push.depth, 3.f);
}

// The landing the sheet describes, as pushOut sees it: only the left 12 pixels of the player
// are over the ledge, and the left-bottom corner has sunk 2.5 pixels into its top (the
// bottom point, in the middle of the player, misses the ledge).
TEST(Task2LeastPenetration, LandingWithOnlyACornerOnALedgeStandsOnIt)
{
    const CollisionPoint& leftBottom = PlatformerLevel::collisionPoints[6];
    const hitbox::Box ledgeEnd{platformertest::ledgeRight - TileMap::tileSize,
                               platformertest::ledgeTop, TileMap::tileSize, TileMap::tileSize};
    const hitbox::Vec2 corner{platformertest::ledgeRight - 12.f, platformertest::ledgeTop + 2.5f};
    const hitbox::Contact push = PlatformerLevel::pushOut(leftBottom, corner, ledgeEnd);
    ASSERT_TRUE(push.hit) << "the corner on the ledge must hold the player up";
    EXPECT_EQ(push.normal, hitbox::Vec2(0.f, -1.f)) << "up onto the ledge, not off it";
    EXPECT_FLOAT_EQ(push.depth, 2.5f);
    EXPECT_EQ(push.point, hitbox::Vec2(corner.x, platformertest::ledgeTop));
}

TEST(Task2LeastPenetration, ACornerAsDeepBothWaysIsPushedAlongX)
{
    const CollisionPoint& rightTop = PlatformerLevel::collisionPoints[5];
    const hitbox::Box tile{64.f, 64.f, 32.f, 32.f};
    // 4 pixels past the tile's left edge and 4 above its bottom edge: a tie.
    const hitbox::Contact push = PlatformerLevel::pushOut(rightTop, {68.f, 92.f}, tile);
    ASSERT_TRUE(push.hit);
    EXPECT_EQ(push.normal, hitbox::Vec2(-1.f, 0.f)) << "the sheet: on a tie, use x";
    EXPECT_FLOAT_EQ(push.depth, 4.f);
}

// ---- Task 3: only the tiles under the swept bounds ------------------------------------------

TEST(Task3SweptBounds, OnlyTheTilesAroundThePlayerAreTested)
{
    Game game(platformertest::deepShaft(40) /* 5 x 40 = 200 tiles */);
    game.level.setWholeMapSearch(false); // the region task 3 finds
    int mostTested = 0;
    for (int frame = 0; frame < 240; ++frame)
    {
        game.fall(hitbox::stepSeconds);
        mostTested = std::max(mostTested, game.level.getTestedRegion().tileCount());
    }
    // 32 x 60 pixels, moving under 16 pixels a step, 48-pixel tiles: at most 2 x 3 tiles.
    EXPECT_LE(mostTested, 6);
    EXPECT_GT(mostTested, 0);
}

TEST(Task3SweptBounds, TheSweptBoundsHoldWhereThePlayerWasAndIs)
{
    Game game(platformertest::deepShaft(40));
    game.level.setWholeMapSearch(false); // the region task 3 finds
    game.fall(0.5f);
    const hitbox::Box before = game.level.getPlayer().getBox();
    game.fall(hitbox::stepSeconds);
    const hitbox::Box after = game.level.getPlayer().getBox();
    const hitbox::Box swept = game.level.getSweptBounds();
    EXPECT_LE(swept.top, before.top);
    EXPECT_GE(swept.top + swept.height, after.top + after.height);
    const TileRegion region = game.level.getTestedRegion();
    EXPECT_EQ(region.firstRow, static_cast<int>(before.top / TileMap::tileSize));
    EXPECT_EQ(region.lastRow,
              static_cast<int>(std::ceil((after.top + after.height) / TileMap::tileSize)) - 1);
}

// ---- Task 4: the speed cap against tunnelling -----------------------------------------------

// The task-4 tests fall at the dive speed (13 500 px/s, the lab's ready-made dive key) down a
// 100-row shaft: fast enough to tunnel. The speed is set before every step, whatever task 1's
// gravity does, and a test stops at the landing (fallUntilLanded), before a jump could
// matter: one mistake in task 1 costs task 1 alone.
constexpr int shaftRows = 100;

TEST(Task4SpeedCap, ADiveFromHighUpLandsOnAFloorOneTileThick)
{
    Game game(platformertest::deepShaft(shaftRows)); // a 4 800 pixel drop
    // At the capped speed the drop takes under 2.2 s.
    const bool landed = game.fallUntilLanded(3.f, Player::diveSpeed);
    EXPECT_EQ(game.level.getFallsOutOfWorld(), 0) << "the player went through the floor";
    EXPECT_TRUE(landed);
    EXPECT_NEAR(game.feet(), (shaftRows - 1) * TileMap::tileSize, 0.01f);
    EXPECT_EQ(game.velocity().y, 0.f) << "the floor stopped the fall";
}

TEST(Task4SpeedCap, EveryStepMovesLessThanATileEvenWhenDiving)
{
    Game game(platformertest::deepShaft(shaftRows));
    for (int frame = 0; frame < 120; ++frame)
    {
        const float before = game.position().y;
        if (game.fallUntilLanded(hitbox::stepSeconds, Player::diveSpeed))
            break;
        EXPECT_LT(game.position().y - before, TileMap::tileSize);
    }
}

// The sheet: clamp the vertical velocity to +-maxFallSpeed. Speeds within it (a jump, a
// slow fall) are left alone; faster ones, up or down, become the cap. Judged against the same
// player stepped with the cap off, so it holds whatever task 1's gravity does.
TEST(Task4SpeedCap, SpeedsWithinTheCapAreLeftAloneFasterOnesAreCapped)
{
    for (const float speed : {-5000.f, -Player::jumpSpeed, 0.f, 1000.f, 5000.f, Player::diveSpeed})
    {
        Player capped({100.f, 100.f});
        Player free({100.f, 100.f});
        capped.setVelocity({0.f, speed});
        free.setVelocity({0.f, speed});
        capped.steer(PlayerControls{}, false, true, hitbox::stepSeconds);
        free.steer(PlayerControls{}, false, false, hitbox::stepSeconds);
        const float uncapped = free.getVelocity().y;
        const float expected = uncapped > Player::maxFallSpeed    ? Player::maxFallSpeed
                               : uncapped < -Player::maxFallSpeed ? -Player::maxFallSpeed
                                                                  : uncapped;
        EXPECT_FLOAT_EQ(capped.getVelocity().y, expected)
            << "starting at " << speed << " px/s (" << uncapped << " px/s without the cap)";
    }
}

// ---- Task 4 (with the lab's ready-made parts): the problem the cap solves, the other cure ----

// A dive moves 112 px a step: more than a tile, less than a tile and the player's height,
// so whether a step ends inside the floor (caught) or past it (gone) depends on the drop
// height. Over twelve drop heights, without the cap, several go through.
TEST(Task4Tunnelling, WithoutTheCapAFastFallGoesThroughTheFloor)
{
    int throughTheFloor = 0;
    for (int rows = 60; rows < 72; ++rows)
    {
        Game game(platformertest::deepShaft(rows));
        game.level.setSpeedCap(false);
        game.fallUntilLanded(0.5f, Player::diveSpeed); // under 3 500 px: 0.26 s
        throughTheFloor += game.level.getFallsOutOfWorld() > 0 ? 1 : 0;
    }
    EXPECT_GE(throughTheFloor, 3)
        << "the bullet-through-paper problem this lab shows has gone away?";
}

TEST(Task4SpeculativeContacts, StopAFastFallOnAThinFloorWithoutTheCap)
{
    Game game(platformertest::deepShaft(shaftRows));
    game.level.setSpeedCap(false);
    game.level.setSpeculativeContacts(true);
    // 4 800 px at 13 500 px/s: under half a second.
    const bool landed = game.fallUntilLanded(1.f, Player::diveSpeed);
    EXPECT_EQ(game.level.getFallsOutOfWorld(), 0);
    EXPECT_TRUE(landed);
    EXPECT_NEAR(game.feet(), (shaftRows - 1) * TileMap::tileSize, 0.01f);
    EXPECT_EQ(game.velocity().y, 0.f) << "the floor stopped the fall";
}

TEST(Task4SpeculativeContacts, PlayerRunsAndStopsAtAWallLikeTheDiscreteVersion)
{
    Game game(platformertest::room);
    game.level.setSpeculativeContacts(true);
    game.input.setKeyDown(sf::Keyboard::Key::D);
    game.fall(3.f);
    EXPECT_NEAR(game.position().x + Player::width, 9 * TileMap::tileSize, 0.01f);
    EXPECT_NEAR(game.feet(), platformertest::roomFloorTop, 0.01f);
    EXPECT_TRUE(game.level.isGrounded());
}

// ---- Ready-made: movement, walls, grounded --------------------------------------------------

TEST(Movement, RunningSpeedsUpToTheTopSpeedAndNoFurther)
{
    Game game(platformertest::room);
    game.run(1.f);
    game.input.setKeyDown(sf::Keyboard::Key::D);
    game.run(0.05f);
    EXPECT_NEAR(game.velocity().x, Player::runAcceleration * 0.05f, 1.f);
    game.run(0.5f);
    EXPECT_FLOAT_EQ(game.velocity().x, Player::maxRunSpeed);
}

TEST(Movement, LettingGoBrakesToAStopFasterThanStartingUp)
{
    Game game(platformertest::room);
    game.run(1.f);
    game.input.setKeyDown(sf::Keyboard::Key::A);
    game.run(0.4f);
    game.input.setKeyUp(sf::Keyboard::Key::A);
    int stepsToStop = 0;
    while (game.velocity().x != 0.f && stepsToStop < 1000)
    {
        game.frame();
        ++stepsToStop;
    }
    EXPECT_EQ(game.velocity().x, 0.f) << "stops, and does not wobble past zero";
    const float secondsToStop = static_cast<float>(stepsToStop) * hitbox::stepSeconds;
    EXPECT_LT(secondsToStop, Player::maxRunSpeed / Player::runAcceleration);
}

TEST(Task1Movement, RunningIntoAWallStopsFlushAgainstIt)
{
    Game game(platformertest::room);
    game.level.setSpeedCap(false); // as in Task1Gravity
    game.input.setKeyDown(sf::Keyboard::Key::A);
    game.run(3.f);
    EXPECT_NEAR(game.position().x, TileMap::tileSize, 0.01f);
    EXPECT_EQ(game.velocity().x, 0.f);
    EXPECT_TRUE(game.level.isGrounded()) << "the floor still holds the player";
}

TEST(Movement, SameKeysGiveTheSameJumpAtAnyFrameRate)
{
    // Run right for half a second, jump, and keep running for a second; compare where the
    // player ends up when the program runs at 30, 60, 120 and 240 frames a second.
    auto play = [](float framesPerSecond)
    {
        Game game(platformertest::room);
        const float dt = 1.f / framesPerSecond;
        game.run(0.5f, dt);
        game.input.setKeyDown(sf::Keyboard::Key::D);
        game.run(0.5f, dt);
        game.tap(sf::Keyboard::Key::Space, dt);
        game.run(0.3f - dt, dt); // the tap was one frame of the 0.3 s
        return game.position();
    };
    const hitbox::Vec2 reference = play(120.f);
    for (float framesPerSecond : {30.f, 60.f, 240.f})
    {
        const hitbox::Vec2 position = play(framesPerSecond);
        EXPECT_EQ(position.x, reference.x) << framesPerSecond << " frames a second";
        EXPECT_EQ(position.y, reference.y) << framesPerSecond << " frames a second";
    }
    EXPECT_LT(reference.y, platformertest::roomFloorTop - Player::height - 30.f)
        << "the script should catch the player in mid-jump";
}

TEST(Task1Grounded, WalkingOffALedgeIsNotGrounded)
{
    Game game(platformertest::roomWithLedge);
    game.level.setSpeedCap(false); // as in Task1Gravity
    game.level.placePlayer({64.f, platformertest::ledgeTop - Player::height});
    game.run(0.1f);
    ASSERT_TRUE(game.level.isGrounded());
    game.input.setKeyDown(sf::Keyboard::Key::D);
    while (game.position().x < platformertest::ledgeRight + 1.f)
        game.frame();
    game.frame();
    EXPECT_FALSE(game.level.isGrounded());
}

TEST(Grounded, PressedAgainstAWallInTheAirIsNotGrounded)
{
    Game game(platformertest::room);
    game.level.placePlayer({60.f, 60.f});
    game.input.setKeyDown(sf::Keyboard::Key::A);
    game.run(0.15f);
    EXPECT_NEAR(game.position().x, TileMap::tileSize, 0.01f) << "against the left wall";
    EXPECT_FALSE(game.level.isGrounded());
}

TEST(DebugView, ShowsTestedTilesPointsAndContacts)
{
    Game game(platformertest::room);
    game.run(1.f);
    hitbox::DebugRenderer debug;
    game.level.renderDebug(debug);
    EXPECT_GT(debug.getVertices().getVertexCount(), 100u);
}

TEST(CollisionPoints, AreCheckedSidesFirstThenCorners)
{
    const char* expected[] = {"bottom",   "top",       "left",        "right",
                              "left top", "right top", "left bottom", "right bottom"};
    ASSERT_EQ(PlatformerLevel::collisionPoints.size(), 8u);
    for (std::size_t index = 0; index < 8; ++index)
        EXPECT_STREQ(PlatformerLevel::collisionPoints[index].name, expected[index]);
}

TEST(CollisionPoints, SitOnTheEdgesAndCornersOfThePlayersBox)
{
    const hitbox::Box box{100.f, 200.f, Player::width, Player::height};
    EXPECT_EQ(PlatformerLevel::pointOn(box, PlatformerLevel::collisionPoints[0]),
              hitbox::Vec2(100.f + Player::width / 2.f, 200.f + Player::height));
    EXPECT_EQ(PlatformerLevel::pointOn(box, PlatformerLevel::collisionPoints[4]),
              hitbox::Vec2(100.f, 200.f));
    EXPECT_EQ(PlatformerLevel::pointOn(box, PlatformerLevel::collisionPoints[7]),
              hitbox::Vec2(100.f + Player::width, 200.f + Player::height));
}
