// Grading tests of lab 9, tasks 5-7: one-way platforms, slopes and checkpoints (triggers).
// Tasks 5 and 6 are checked as functions (against the framework's oneWayPlatformStop and
// standOnSlope, which follow the same rules) and in the level; task 7 in the level. The level
// tests script the player's velocity (setSteering(false)): no gravity, jump or speed cap, so
// a mistake in task 1 or 4 costs those tasks alone.
#include "PlatformerTestSupport.h"
#include "Platforms.h"

#include "hitbox/geometry/OneWayPlatform.h"
#include "hitbox/geometry/Slope.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <random>
#include <string>

namespace
{
struct Scripted : platformertest::Game
{
    explicit Scripted(const std::string& mapText) : Game(mapText) { level.setSteering(false); }
    // `steps` steps at `velocity` (pixels per second), set again before each step.
    void move(hitbox::Vec2 velocity, int steps)
    {
        for (int index = 0; index < steps; ++index)
        {
            level.setPlayerVelocity(velocity);
            frame();
        }
    }
};

// ---- Task 5 ----------------------------------------------------------------------------
// A room with a one-way platform: its top is y = 240, from x = 144 to 336. The player starts
// on the floor (y = 432) under it, from x = 200 to 232.
const char* const plankRoom = "##########\n"
                              "#........#\n"
                              "#........#\n"
                              "#........#\n"
                              "#........#\n"
                              "#..----..#\n"
                              "#........#\n"
                              "#........#\n"
                              "#...P....#\n"
                              "##########\n";
const float plankTop = 240.f;
const hitbox::Box plank{144.f, 240.f, 48.f, 48.f};

// The top-left corner of a box (where placePlayer puts the player).
hitbox::Vec2 topLeft(const hitbox::Box& box)
{
    return {box.left, box.top};
}

// A 32 x 60 player whose bottom is at `bottom`, left edge at `left`.
hitbox::Box playerAt(float left, float bottom)
{
    return {left, bottom - Player::height, Player::width, Player::height};
}
} // namespace

TEST(Task5OneWay, AFallOntoItStopsOnTheTop)
{
    // Bottom at 230, falling 15: it would end 5 px into the platform; it stops after 10.
    const hitbox::OneWayStop stop = landOnOneWay(playerAt(150.f, 230.f), {2.f, 15.f}, plank);
    ASSERT_TRUE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 10.f);
    EXPECT_FLOAT_EQ(stop.move.x, 2.f);
}

TEST(Task5OneWay, StandingOnItHolds)
{
    // Touching counts as above: gravity's small step down is cut to nothing.
    const hitbox::OneWayStop stop = landOnOneWay(playerAt(150.f, plankTop), {0.f, 0.25f}, plank);
    ASSERT_TRUE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 0.f);
}

TEST(Task5OneWay, MovingUpOrStillIsNeverCaught)
{
    for (const float bottom : {300.f, 260.f, plankTop, 200.f})
    {
        const hitbox::OneWayStop up = landOnOneWay(playerAt(150.f, bottom), {0.f, -9.5f}, plank);
        EXPECT_FALSE(up.blocked) << "bottom " << bottom;
        EXPECT_FLOAT_EQ(up.move.y, -9.5f);
        EXPECT_FALSE(landOnOneWay(playerAt(150.f, bottom), {3.f, 0.f}, plank).blocked);
    }
}

TEST(Task5OneWay, FallingBackAfterHalfAJumpThroughIsNotCaught)
{
    // The jump peaked with the bottom 1 px below the top: falling back is no landing.
    const hitbox::OneWayStop stop = landOnOneWay(playerAt(150.f, 241.f), {0.f, 5.f}, plank);
    EXPECT_FALSE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 5.f);
}

TEST(Task5OneWay, EndingExactlyOnTheTopIsTouchingNotABlock)
{
    const hitbox::OneWayStop stop = landOnOneWay(playerAt(150.f, 230.f), {0.f, 10.f}, plank);
    EXPECT_FALSE(stop.blocked);
    EXPECT_FLOAT_EQ(stop.move.y, 10.f);
}

TEST(Task5OneWay, BesideItOrTouchingItsEndFallsPast)
{
    EXPECT_FALSE(landOnOneWay(playerAt(192.f, 230.f), {0.f, 15.f}, plank).blocked); // right end
    EXPECT_FALSE(landOnOneWay(playerAt(112.f, 230.f), {0.f, 15.f}, plank).blocked); // left end
    EXPECT_TRUE(landOnOneWay(playerAt(191.f, 230.f), {0.f, 15.f}, plank).blocked);  // 1 px on
    EXPECT_TRUE(landOnOneWay(playerAt(113.f, 230.f), {0.f, 15.f}, plank).blocked);
}

TEST(Task5OneWay, WhereThePlayerIsWhenItsBottomReachesTheTopDecides)
{
    // Moving right 40 while falling 20: the bottom reaches the top half-way (t = 0.5).
    // Over the platform then, past its end by the end of the move: lands.
    EXPECT_TRUE(landOnOneWay(playerAt(170.f, 230.f), {40.f, 20.f}, plank).blocked);
    // Beside it then, over it only by the end of the move: falls past.
    EXPECT_FALSE(landOnOneWay(playerAt(80.f, 230.f), {40.f, 20.f}, plank).blocked);
}

TEST(Task5OneWay, AgreesWithTheFrameworksRuleOnRandomMoves)
{
    std::mt19937 random(5);
    // Quarter pixels: the sums are exact, so only the rule can make an answer differ.
    std::uniform_int_distribution<int> quarter(-160, 160);
    int blocked = 0;
    for (int trial = 0; trial < 4000; ++trial)
    {
        const hitbox::Box player =
            playerAt(160.f + quarter(random) / 4.f * 2.f, plankTop + quarter(random) / 16.f);
        const hitbox::Vec2 move{quarter(random) / 8.f, quarter(random) / 8.f};
        const hitbox::OneWayStop expected = hitbox::oneWayPlatformStop(player, move, plank);
        const hitbox::OneWayStop got = landOnOneWay(player, move, plank);
        ASSERT_EQ(got.blocked, expected.blocked)
            << "player at (" << player.left << ", " << player.top << "), move (" << move.x << ", "
            << move.y << ")";
        EXPECT_FLOAT_EQ(got.move.y, expected.move.y);
        EXPECT_FLOAT_EQ(got.move.x, expected.move.x);
        blocked += expected.blocked ? 1 : 0;
    }
    EXPECT_GT(blocked, 250); // many of the moves land: the test is not all "falls past"
}

TEST(Task5OneWay, InTheLevelAJumpGoesUpThroughItAndLandsOnIt)
{
    Scripted game(plankRoom);
    ASSERT_FLOAT_EQ(game.feet(), platformertest::roomFloorTop);
    game.move({0.f, -900.f}, 30); // 7.5 px a step, 225 px up: through the platform
    EXPECT_FLOAT_EQ(game.feet(), platformertest::roomFloorTop - 225.f);
    game.move({0.f, 600.f}, 30); // falling back down onto it
    EXPECT_FLOAT_EQ(game.feet(), plankTop);
    EXPECT_TRUE(game.level.isGrounded());
}

TEST(Task5OneWay, InTheLevelAPlayerStandsOnItUntilItWalksOffTheEnd)
{
    Scripted game(plankRoom);
    game.level.placePlayer(topLeft(playerAt(200.f, 150.f)));
    game.move({0.f, 600.f}, 30);
    ASSERT_FLOAT_EQ(game.feet(), plankTop);
    for (int step = 0; step < 40; ++step) // walking right, pressed down: held on the top
    {
        game.move({120.f, 300.f}, 1);
        EXPECT_FLOAT_EQ(game.feet(), plankTop) << "step " << step;
        EXPECT_TRUE(game.level.isGrounded()) << "step " << step;
    }
    game.move({600.f, 600.f}, 80); // off the end (x = 336): it falls to the floor
    EXPECT_FLOAT_EQ(game.feet(), platformertest::roomFloorTop);
}

namespace
{
// ---- Task 6 ----------------------------------------------------------------------------
// A 45-degree slope tile rising to the right: from (288, 432) up to (336, 384), with a
// block to its right whose top is y = 384. The player starts on the floor, left edge 104.
const char* const rampRoom = "##########\n"
                             "#........#\n"
                             "#........#\n"
                             "#........#\n"
                             "#........#\n"
                             "#........#\n"
                             "#........#\n"
                             "#........#\n"
                             "#.P.../###\n"
                             "##########\n";
const hitbox::Slope ramp{{288.f, 432.f}, {336.f, 384.f}};
const float snap = PlatformerLevel::slopeSnapDistance;

// A player whose foot (the middle of its bottom) is at (x, y).
hitbox::Box footAt(float x, float y)
{
    return playerAt(x - Player::width / 2.f, y);
}
float footX(const Scripted& game)
{
    return game.position().x + Player::width / 2.f;
}
// The foot strictly between the slope's ends (at an end the floor or the block takes over).
bool overTheRamp(const Scripted& game)
{
    return footX(game) > ramp.left.x && footX(game) < ramp.right.x;
}
} // namespace

TEST(Task6Slope, AFootBelowTheSurfaceIsPushedUpOntoIt)
{
    // x = 312: the surface is at y = 408; the foot is 3 px into the slope.
    const hitbox::SlopeFoot foot = footOnSlope(footAt(312.f, 411.f), 0.f, ramp, snap);
    ASSERT_TRUE(foot.grounded);
    EXPECT_FLOAT_EQ(foot.moveY, -3.f);
}

TEST(Task6Slope, AFootALittleAboveIsPulledDownOntoItAndHigherIsInTheAir)
{
    const hitbox::SlopeFoot foot = footOnSlope(footAt(312.f, 404.5f), 0.f, ramp, snap);
    ASSERT_TRUE(foot.grounded);
    EXPECT_FLOAT_EQ(foot.moveY, 3.5f);
    EXPECT_TRUE(footOnSlope(footAt(312.f, 408.f - snap), 0.f, ramp, snap).grounded);
    EXPECT_FALSE(footOnSlope(footAt(312.f, 407.f - snap), 0.f, ramp, snap).grounded);
    // With no snapping (a falling player), only a foot on or in the slope stands.
    EXPECT_FALSE(footOnSlope(footAt(312.f, 407.f), 0.f, ramp, 0.f).grounded);
    const hitbox::SlopeFoot on = footOnSlope(footAt(312.f, 408.f), 0.f, ramp, 0.f);
    EXPECT_TRUE(on.grounded);
    EXPECT_FLOAT_EQ(on.moveY, 0.f);
}

TEST(Task6Slope, ARisingPlayerIsNeverMoved)
{
    for (const float y : {404.f, 408.f, 411.f})
    {
        const hitbox::SlopeFoot foot = footOnSlope(footAt(312.f, y), -600.f, ramp, snap);
        EXPECT_FALSE(foot.grounded) << "foot at y " << y;
        EXPECT_FLOAT_EQ(foot.moveY, 0.f);
    }
}

TEST(Task6Slope, OnlyTheMiddleOfTheBottomCounts)
{
    // The box's right half is over the slope but its foot is beside it: nothing.
    EXPECT_FALSE(footOnSlope(footAt(280.f, 436.f), 0.f, ramp, snap).grounded);
    // The foot over the slope's end, the box's right half over the block: stands.
    const hitbox::SlopeFoot end = footOnSlope(footAt(336.f, 386.f), 0.f, ramp, snap);
    EXPECT_TRUE(end.grounded);
    EXPECT_FLOAT_EQ(end.moveY, -2.f);
    EXPECT_FLOAT_EQ(footOnSlope(footAt(288.f, 430.f), 0.f, ramp, snap).moveY, 2.f);
}

TEST(Task6Slope, AFootUnderTheSlopeIsNotLiftedOntoIt)
{
    // Lower than the slope's lowest end (y = 432): in the tile below, not on the slope.
    EXPECT_FALSE(footOnSlope(footAt(312.f, 433.f), 0.f, ramp, snap).grounded);
    EXPECT_FLOAT_EQ(footOnSlope(footAt(312.f, 432.f), 0.f, ramp, snap).moveY, -24.f);
}

TEST(Task6Slope, AgreesWithTheFrameworksRuleOnRandomFeet)
{
    std::mt19937 random(6);
    std::uniform_real_distribution<float> x(270.f, 350.f);
    std::uniform_real_distribution<float> y(370.f, 440.f);
    std::uniform_real_distribution<float> velocity(-60.f, 60.f);
    std::uniform_real_distribution<float> pull(0.f, 20.f);
    const hitbox::Slope slopes[] = {ramp, {{288.f, 384.f}, {336.f, 432.f}}};
    int grounded = 0;
    for (int trial = 0; trial < 4000; ++trial)
    {
        const hitbox::Box box = footAt(x(random), y(random));
        const float vy = velocity(random);
        const float distance = pull(random);
        const hitbox::Slope& slope = slopes[trial % 2];
        const hitbox::SlopeFoot expected = hitbox::standOnSlope(box, vy, slope, distance);
        const hitbox::SlopeFoot got = footOnSlope(box, vy, slope, distance);
        ASSERT_EQ(got.grounded, expected.grounded)
            << "foot at (" << box.left + 16.f << ", " << box.top + 60.f << "), velocity " << vy
            << ", snap " << distance;
        EXPECT_NEAR(got.moveY, expected.moveY, 1e-3f);
        grounded += expected.grounded ? 1 : 0;
    }
    EXPECT_GT(grounded, 400); // many feet stand: the test is not all "in the air"
}

TEST(Task6Slope, InTheLevelThePlayerWalksUpTheSlopeOnItsSurface)
{
    Scripted game(rampRoom);
    int onSlope = 0;
    for (int step = 0; step < 150; ++step)
    {
        game.move({240.f, 30.f}, 1); // 2 px a step to the right, pressed down a little
        if (!overTheRamp(game))
            continue;
        const hitbox::SlopeGround ground = hitbox::slopeGroundAt(ramp, footX(game));
        ++onSlope;
        EXPECT_NEAR(game.feet(), ground.y, 1e-3f) << "foot at x " << footX(game);
        EXPECT_TRUE(game.level.isGrounded()) << "foot at x " << footX(game);
    }
    EXPECT_GE(onSlope, 20);
    EXPECT_FLOAT_EQ(game.feet(), 384.f); // on the block at the top
    EXPECT_GT(game.position().x, 340.f);
}

TEST(Task6Slope, InTheLevelWalkingDownTheSlopeNeverLeavesIt)
{
    Scripted game(rampRoom);
    game.level.placePlayer(topLeft(footAt(370.f, 384.f)));
    game.move({0.f, 300.f}, 2); // stand on the block
    ASSERT_TRUE(game.level.isGrounded());
    int onSlope = 0;
    for (int step = 0; step < 60; ++step)
    {
        game.move({-420.f, 30.f}, 1); // 3.5 px a step: the ground drops 3.5 px under the foot
        if (!overTheRamp(game))
            continue;
        ++onSlope;
        EXPECT_TRUE(game.level.isGrounded()) << "foot at x " << footX(game);
        EXPECT_NEAR(game.feet(), hitbox::slopeGroundAt(ramp, footX(game)).y, 1e-3f)
            << "foot at x " << footX(game);
    }
    EXPECT_GE(onSlope, 12);
    EXPECT_FLOAT_EQ(game.feet(), platformertest::roomFloorTop); // down on the floor
}

TEST(Task6Slope, InTheLevelAJumpLeavesTheSlope)
{
    Scripted game(rampRoom);
    game.level.placePlayer(topLeft(footAt(312.f, 400.f)));
    game.move({0.f, 300.f}, 5); // land on the slope: the foot at y 408
    ASSERT_FLOAT_EQ(game.feet(), 408.f);
    ASSERT_TRUE(game.level.isGrounded());
    game.move({0.f, -600.f}, 10); // 5 px a step up, less than the snap distance
    EXPECT_FLOAT_EQ(game.feet(), 358.f);
    EXPECT_FALSE(game.level.isGrounded());
}

namespace
{
// ---- Task 7 ----------------------------------------------------------------------------
// A checkpoint on the floor: its zone is x 288..336, y 384..432. The player starts on the
// floor with its left edge at 104.
std::string checkpointRoom(char checkpoint)
{
    return std::string("##########\n") + "#........#\n" + "#........#\n" + "#........#\n" +
           "#........#\n" + "#........#\n" + "#........#\n" + "#........#\n" + "#.P..." +
           checkpoint + "..#\n" + "##########\n";
}
const hitbox::Vec2 checkpointTile{288.f, 384.f};
const hitbox::Vec2 startTile{96.f, 384.f};
} // namespace

TEST(Task7Checkpoint, WalkingThroughItIsOneEntry)
{
    Scripted game(checkpointRoom('C'));
    EXPECT_EQ(game.level.getCheckpointEntries(), 0);
    EXPECT_EQ(game.level.getRespawnTile(), startTile);
    game.move({240.f, 0.f}, 150);
    EXPECT_EQ(game.level.getCheckpointEntries(), 1);
    EXPECT_EQ(game.level.getRespawnTile(), checkpointTile);
}

TEST(Task7Checkpoint, ItNeverPushes)
{
    // The same walk, right and back, with the checkpoint and with an empty tile: the player
    // goes exactly the same way (a trigger reports; it does not block or slow).
    Scripted with(checkpointRoom('C'));
    Scripted without(checkpointRoom('.'));
    for (int step = 0; step < 240; ++step)
    {
        const hitbox::Vec2 velocity{step < 120 ? 240.f : -300.f, step % 3 == 0 ? 60.f : 0.f};
        with.move(velocity, 1);
        without.move(velocity, 1);
        ASSERT_EQ(with.position(), without.position()) << "step " << step;
        ASSERT_EQ(with.velocity(), without.velocity()) << "step " << step;
        ASSERT_EQ(with.level.isGrounded(), without.level.isGrounded()) << "step " << step;
    }
    EXPECT_EQ(with.level.getCheckpointEntries(), 2); // in on the way right, in on the way back
}

TEST(Task7Checkpoint, StayingInsideIsStillOneEntry)
{
    Scripted game(checkpointRoom('C'));
    game.move({240.f, 0.f}, 95); // left edge 294: inside the zone
    ASSERT_EQ(game.level.getCheckpointEntries(), 1);
    game.move({0.f, 0.f}, 120);
    EXPECT_EQ(game.level.getCheckpointEntries(), 1);
}

TEST(Task7Checkpoint, TouchingItsEdgeIsNotEnteringIt)
{
    Scripted game(checkpointRoom('C'));
    game.level.placePlayer({checkpointTile.x - Player::width, 372.f}); // right edge on x = 288
    game.move({0.f, 0.f}, 10);
    EXPECT_EQ(game.level.getCheckpointEntries(), 0);
    game.move({60.f, 0.f}, 1); // half a pixel in
    EXPECT_EQ(game.level.getCheckpointEntries(), 1);
}

TEST(Task7Checkpoint, RestartingGoesToTheLastCheckpointEntered)
{
    Scripted game(checkpointRoom('C'));
    game.move({240.f, 0.f}, 40); // not there yet
    game.tap(sf::Keyboard::Key::R);
    EXPECT_EQ(game.position(), hitbox::Vec2(104.f, 372.f)); // back at 'P'
    game.move({240.f, 0.f}, 150);
    game.tap(sf::Keyboard::Key::R);
    EXPECT_EQ(game.position(), hitbox::Vec2(checkpointTile.x + 8.f, 372.f)); // at the flag
    EXPECT_EQ(game.level.getCheckpointEntries(), 1); // restarting inside it is no new entry
}
