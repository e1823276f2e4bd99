// The rules of a match: points, serves, winning, screens and keys.
#include "PongTestHelpers.h"

#include <gtest/gtest.h>

using pongtest::step;
using pongtest::steps;
using pongtest::stepsFor;

namespace
{
PongSettings twoPlayerSettings(int pointsToWin = 11)
{
    PongSettings settings;
    settings.mode = Mode::TwoPlayers; // nobody presses a key: the paddles stay still
    settings.pointsToWin = pointsToWin;
    return settings;
}

// Sends the ball off the `side` edge, above the (still) paddles, and steps until the point.
void loseAPoint(PongLevel& pong, Side side)
{
    const float x = side == Side::Left ? 200.f : pong.getArena().size.x - 200.f;
    pong.placeBall({x, 80.f}, {directionOf(side) * 900.f, 0.f});
    const int pointsBefore =
        pong.getScore().pointsOf(Side::Left) + pong.getScore().pointsOf(Side::Right);
    hitbox::Input input;
    for (int i = 0; i < 600; ++i)
    {
        step(pong, input);
        if (pong.getScore().pointsOf(Side::Left) + pong.getScore().pointsOf(Side::Right) >
            pointsBefore)
            return;
    }
}
} // namespace

TEST(PongScoring, BallLeavingTheLeftSideIsAPointForTheRightPlayer)
{
    PongLevel pong(twoPlayerSettings());
    pong.startMatch(Mode::TwoPlayers);
    loseAPoint(pong, Side::Left);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Right), 1);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Left), 0);
    EXPECT_EQ(pong.getEvents(), std::vector<GameEvent>{GameEvent::Point});
}

TEST(PongScoring, BallLeavingTheRightSideIsAPointForTheLeftPlayer)
{
    PongLevel pong(twoPlayerSettings());
    pong.startMatch(Mode::TwoPlayers);
    loseAPoint(pong, Side::Right);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Left), 1);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Right), 0);
}

TEST(PongServe, AfterAPointTheBallWaitsInTheMiddleThenGoesTowardsThePlayerWhoLostIt)
{
    for (Side loser : {Side::Left, Side::Right})
    {
        PongLevel pong(twoPlayerSettings());
        pong.startMatch(Mode::TwoPlayers);
        loseAPoint(pong, loser);
        ASSERT_TRUE(pong.isServing());
        EXPECT_EQ(pong.getServeSide(), loser);
        EXPECT_FLOAT_EQ(pong.getBall().getPosition().x, pong.getArena().centerX());
        EXPECT_FALSE(pong.getBall().isMoving());

        steps(pong, stepsFor(1.1f)); // the serve delay is 1 s
        EXPECT_FALSE(pong.isServing());
        EXPECT_EQ(pong.getBall().getVelocity().x > 0.f ? Side::Right : Side::Left, loser)
            << nameOf(loser) << " lost the point";
        EXPECT_FLOAT_EQ(pong.getBall().getSpeed(), pong.getBall().getSettings().serveSpeed);
    }
}

TEST(PongMatch, FirstToThePointsToWinWinsAndTheWinScreenShows)
{
    PongLevel pong(twoPlayerSettings(3));
    pong.startMatch(Mode::TwoPlayers);
    loseAPoint(pong, Side::Left);
    loseAPoint(pong, Side::Right);
    loseAPoint(pong, Side::Left);
    EXPECT_EQ(pong.getScreen(), Screen::Play);
    loseAPoint(pong, Side::Left);
    EXPECT_EQ(pong.getScreen(), Screen::Win);
    EXPECT_EQ(pong.getScore().getWinner(), Side::Right);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Right), 3);
    EXPECT_EQ(pong.getEvents(), (std::vector<GameEvent>{GameEvent::Point, GameEvent::MatchWon}));
}

TEST(PongMatch, SpaceOnTheWinScreenStartsARematchFromNilNil)
{
    PongLevel pong(twoPlayerSettings());
    pong.showWinScreen(11, 4);
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Space);
    step(pong, input);
    EXPECT_EQ(pong.getScreen(), Screen::Play);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Left), 0);
    EXPECT_EQ(pong.getScore().pointsOf(Side::Right), 0);
}

TEST(PongMatch, ComputerAgainstComputerStartsTheNextMatchByItself)
{
    PongSettings settings;
    settings.mode = Mode::ComputerVsComputer;
    PongLevel pong(settings);
    pong.startMatch(Mode::ComputerVsComputer);
    pong.showWinScreen(11, 9);
    steps(pong, stepsFor(settings.secondsBeforeRematch + 0.1f));
    EXPECT_EQ(pong.getScreen(), Screen::Play);
    EXPECT_EQ(pong.getMode(), Mode::ComputerVsComputer);
}

TEST(PongScreens, NumberKeysOnTheTitleChooseTheMode)
{
    const std::pair<sf::Keyboard::Key, Mode> choices[] = {
        {sf::Keyboard::Key::Num1, Mode::OnePlayer},
        {sf::Keyboard::Key::Num2, Mode::TwoPlayers},
        {sf::Keyboard::Key::Num3, Mode::ComputerVsComputer}};
    for (const auto& [key, mode] : choices)
    {
        PongLevel pong;
        ASSERT_EQ(pong.getScreen(), Screen::Title);
        hitbox::Input input;
        input.setKeyDown(key);
        step(pong, input);
        EXPECT_EQ(pong.getScreen(), Screen::Play);
        EXPECT_EQ(pong.getMode(), mode);
        EXPECT_FALSE(pong.isAttractMode());
    }
}

TEST(PongScreens, DOnTheTitleChangesTheDifficultyAndArrowsThePointsToWin)
{
    PongLevel pong;
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::D);
    step(pong, input);
    EXPECT_EQ(pong.getDifficulty(), Difficulty::Hard); // normal -> hard
    input.setKeyUp(sf::Keyboard::Key::D);
    input.setKeyDown(sf::Keyboard::Key::Left);
    step(pong, input);
    input.setKeyDown(sf::Keyboard::Key::Num1);
    step(pong, input);
    EXPECT_EQ(pong.getScore().getPointsToWin(), 10);
}

TEST(PongScreens, LeftAloneOnTheTitleTheGamePlaysItselfUntilAKeyIsPressed)
{
    PongLevel pong;
    steps(pong, stepsFor(PongSettings().idleSecondsBeforeAttract + 0.1f));
    EXPECT_TRUE(pong.isAttractMode());
    EXPECT_EQ(pong.getMode(), Mode::ComputerVsComputer);
    steps(pong, stepsFor(3.f));
    EXPECT_TRUE(pong.getBall().isMoving());

    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::F1); // the debug key is not "somebody wants to play"
    step(pong, input);
    EXPECT_TRUE(pong.isAttractMode());
    input.setKeyDown(sf::Keyboard::Key::A);
    step(pong, input);
    EXPECT_EQ(pong.getScreen(), Screen::Title);
}

TEST(PongScreens, EscapeDuringAMatchGoesBackToTheTitleAndOnTheTitleQuits)
{
    PongLevel pong;
    pong.startMatch(Mode::OnePlayer);
    EXPECT_TRUE(pong.handleEscape());
    EXPECT_EQ(pong.getScreen(), Screen::Title);
    EXPECT_FALSE(pong.handleEscape());
}

TEST(PongKeys, WAndSMoveTheLeftPaddleUpAndDownAndArrowsTheRightOne)
{
    PongLevel pong(twoPlayerSettings());
    pong.startMatch(Mode::TwoPlayers);
    const float leftStart = pong.getPaddle(Side::Left).getPosition().y;
    const float rightStart = pong.getPaddle(Side::Right).getPosition().y;
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::W);
    input.setKeyDown(sf::Keyboard::Key::Down);
    for (int i = 0; i < 12; ++i)
        step(pong, input);
    EXPECT_LT(pong.getPaddle(Side::Left).getPosition().y, leftStart);
    EXPECT_GT(pong.getPaddle(Side::Right).getPosition().y, rightStart);
}

TEST(PongKeys, PaddlesStopShortOfTheWallsLeavingRoomForTheBall)
{
    PongLevel pong(twoPlayerSettings());
    pong.startMatch(Mode::TwoPlayers);
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::W);
    for (int i = 0; i < stepsFor(2.f); ++i)
        step(pong, input);
    const float gap =
        hitbox::toBox(pong.getPaddle(Side::Left).getCollisionBox()).top - pong.getArena().playTop();
    EXPECT_GT(gap, pong.getBall().getSettings().size);
}

TEST(PongKeys, MTogglesTheSound)
{
    PongLevel pong;
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::M);
    step(pong, input);
    EXPECT_TRUE(pong.isMuted());
    input.setKeyUp(sf::Keyboard::Key::M);
    step(pong, input);
    input.setKeyDown(sf::Keyboard::Key::M);
    step(pong, input);
    EXPECT_FALSE(pong.isMuted());
}
