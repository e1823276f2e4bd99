// Long games: nothing escapes, nothing becomes NaN, and a seed replays the same game.
#include "PongTestHelpers.h"

#include "hitbox/geometry/Overlap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using pongtest::step;
using pongtest::stepsFor;

namespace
{
// Plays computer against computer for `seconds`, checking every single step.
void playAndCheckEveryStep(float seconds, unsigned seed)
{
    PongSettings settings;
    settings.mode = Mode::ComputerVsComputer;
    settings.seed = seed;
    PongLevel pong(settings);
    pong.startMatch(Mode::ComputerVsComputer);
    const Arena& arena = pong.getArena();
    // A point is scored the step the ball is fully outside, so it is never further out
    // than one step at top speed.
    const float oneStep = pong.getBall().getSettings().maxSpeed * hitbox::stepSeconds;
    const float size = pong.getBall().getSettings().size;
    hitbox::Input noKeys;
    const long long count = stepsFor(seconds);
    for (long long i = 0; i < count; ++i)
    {
        step(pong, noKeys);
        const Ball& ball = pong.getBall();
        const hitbox::Box box = hitbox::toBox(ball.getCollisionBox());
        const Score& score = pong.getScore();
        ASSERT_TRUE(hitbox::isFinite(box) && hitbox::isFinite(hitbox::toVec2(ball.getVelocity())))
            << "step " << i;
        ASSERT_GE(box.top, arena.playTop()) << "step " << i;
        ASSERT_LE(hitbox::bottomOf(box), arena.playBottom()) << "step " << i;
        ASSERT_GT(box.left, -size - oneStep) << "step " << i;
        ASSERT_LT(box.left, arena.size.x + oneStep) << "step " << i;
        ASSERT_LE(ball.getSpeed(), ball.getSettings().maxSpeed + 0.5f) << "step " << i;
        ASSERT_LE(pong.getEvents().size(), 3u) << "the ball is stuck bouncing at step " << i;
        for (Side side : {Side::Left, Side::Right})
        {
            ASSERT_GE(score.pointsOf(side), 0);
            ASSERT_LE(score.pointsOf(side), score.getPointsToWin());
            const hitbox::Box paddle = hitbox::toBox(pong.getPaddle(side).getCollisionBox());
            ASSERT_GE(paddle.top, arena.playTop()) << "step " << i;
            ASSERT_LE(hitbox::bottomOf(paddle), arena.playBottom()) << "step " << i;
            ASSERT_FALSE(hitbox::boxVsBox(paddle, box)) << "ball inside a paddle at step " << i;
        }
    }
    // The hour was really played: matches were won and rallies happened.
    EXPECT_GT(pong.getPaddleHitsTotal(), 100);
    if (seconds >= 3600.f)
    {
        EXPECT_GT(pong.getMatchesFinished(), 1);
    }
}

// Everything a player could see, as text, to compare two runs exactly.
std::string snapshot(const PongLevel& pong)
{
    std::ostringstream text;
    text.precision(9);
    const Ball& ball = pong.getBall();
    text << pong.describeState() << " | " << ball.getPosition().x << " " << ball.getPosition().y
         << " " << ball.getVelocity().x << " " << ball.getVelocity().y << " "
         << pong.getPaddle(Side::Left).getPosition().y << " "
         << pong.getPaddle(Side::Right).getPosition().y;
    return text.str();
}

// One player against the computer, the player following the ball with a scripted rhythm
// of key presses: the same inputs each run.
std::string playScripted(unsigned seed, float seconds)
{
    PongSettings settings;
    settings.seed = seed;
    PongLevel pong(settings);
    pong.startMatch(Mode::OnePlayer);
    hitbox::Input input;
    const long long count = stepsFor(seconds);
    for (long long i = 0; i < count; ++i)
    {
        // Follow the ball, but only on some steps (a person is not a machine).
        if (i % 7 < 4)
            pongtest::steerTowards(input, pong.getPaddle(Side::Left).getPosition().y,
                                   pong.getBall().getPosition().y, 10.f);
        if (pong.getScreen() == Screen::Win && i % 600 == 0)
            input.setKeyDown(sf::Keyboard::Key::Space);
        else
            input.setKeyUp(sf::Keyboard::Key::Space);
        step(pong, input);
    }
    return snapshot(pong);
}
} // namespace

TEST(PongLongRun, TenMinutesOfComputerPlayKeepsEverythingInsideFiniteAndLegal)
{
    playAndCheckEveryStep(600.f, 7);
}

TEST(PongLongRun, AnHourOfComputerPlayKeepsEverythingInsideFiniteAndLegal)
{
    playAndCheckEveryStep(3600.f, 7);
}

TEST(PongLongRun, AnHourWithTheSeedThatOnceTrappedTheBallOnAPaddleStaysClean)
{
    playAndCheckEveryStep(3600.f, 8); // see BallPaddle.ABallGrazingAPaddleCorner...
}

TEST(PongReplay, TheSameSeedAndInputsGiveTheSameGameTwice)
{
    const std::string first = playScripted(42, 300.f);
    const std::string second = playScripted(42, 300.f);
    EXPECT_EQ(first, second);
}

TEST(PongReplay, ADifferentSeedGivesADifferentGame)
{
    EXPECT_NE(playScripted(42, 120.f), playScripted(43, 120.f));
}

TEST(PongReplay, HeadlessComputerPlayWithTheSameSeedEndsTheSame)
{
    auto run = [](unsigned seed)
    {
        PongSettings settings;
        settings.mode = Mode::ComputerVsComputer;
        settings.seed = seed;
        PongLevel pong(settings);
        pong.startMatch(Mode::ComputerVsComputer);
        hitbox::simulate(pong, stepsFor(600.f));
        return snapshot(pong);
    };
    EXPECT_EQ(run(7), run(7));
}
