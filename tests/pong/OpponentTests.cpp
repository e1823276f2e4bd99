// The computer player: beatable on easy, hard to beat on hard. "Good" and "weak" players are
// scripted people: what they see is the ball, what they do is hold W or S.
#include "PongTestHelpers.h"

#include "hitbox/app/Loop.h"

#include <gtest/gtest.h>

#include <cmath>

using pongtest::playMatch;

namespace
{
// Where the ball will cross the left paddle's line, folding wall bounces back in.
float arrivalY(const PongLevel& pong)
{
    const Ball& ball = pong.getBall();
    const Arena& arena = pong.getArena();
    const sf::Vector2f position = ball.getPosition();
    const sf::Vector2f velocity = ball.getVelocity();
    if (velocity.x >= 0.f)
        return arena.centerY(); // going away: wait in the middle
    const float seconds = (pong.getPaddle(Side::Left).getPosition().x - position.x) / velocity.x;
    const float half = ball.getSettings().size / 2.f;
    const float top = arena.playTop() + half;
    const float height = arena.playBottom() - half - top;
    float y = std::fmod(position.y + velocity.y * seconds - top, 2.f * height);
    if (y < 0.f)
        y += 2.f * height;
    if (y > height)
        y = 2.f * height - y;
    return top + y;
}

// A good player: reads the bounce, gets there, and hits a little off-centre to make an
// angle the computer has to chase.
void goodPlayer(const PongLevel& pong, hitbox::Input& input)
{
    const float paddleY = pong.getPaddle(Side::Left).getPosition().y;
    pongtest::steerTowards(input, paddleY, arrivalY(pong) - 25.f, 4.f);
}

// A weak player: follows the ball only when it is already close, and only on some steps.
void weakPlayer(const PongLevel& pong, hitbox::Input& input)
{
    const float paddleY = pong.getPaddle(Side::Left).getPosition().y;
    const bool close = pong.getBall().getPosition().x < pong.getArena().size.x * 0.35f;
    const bool looking = pong.getStepCount() % 10 < 5;
    if (close && looking)
        pongtest::steerTowards(input, paddleY, pong.getBall().getPosition().y, 20.f);
    else
    {
        input.setKeyUp(sf::Keyboard::Key::W);
        input.setKeyUp(sf::Keyboard::Key::S);
    }
}

// A decent player: reads the bounce, but looks only every quarter of a second, and
// misjudges the arrival point more the faster the ball goes.
struct DecentPlayer
{
    float target = 0.f;

    void operator()(const PongLevel& pong, hitbox::Input& input)
    {
        const long long stepNumber = pong.getStepCount();
        const long long quarterSecond = static_cast<long long>(hitbox::stepsPerSecond / 4.f);
        if (stepNumber % quarterSecond == 0)
        {
            const float wobble =
                static_cast<float>((stepNumber / quarterSecond) % 7 - 3) / 3.f; // -1..1
            // 20 px off at the serve speed, more as the ball speeds up.
            const Ball& ball = pong.getBall();
            const float error = 20.f * ball.getSpeed() / ball.getSettings().serveSpeed;
            target = arrivalY(pong) + wobble * error;
        }
        pongtest::steerTowards(input, pong.getPaddle(Side::Left).getPosition().y, target, 8.f);
    }
};

int matchesWonByThePlayer(Difficulty difficulty, const pongtest::Player& player, int matches)
{
    int won = 0;
    for (int match = 0; match < matches; ++match)
    {
        PongSettings settings;
        settings.difficulty = difficulty;
        settings.seed = 100u + static_cast<unsigned>(match);
        PongLevel pong(settings);
        pong.startMatch(Mode::OnePlayer);
        bool finished = false;
        const Side winner = playMatch(pong, player, 3600.f, finished);
        EXPECT_TRUE(finished) << "match " << match << " did not end within an hour";
        if (finished && winner == Side::Left)
            ++won;
    }
    return won;
}
} // namespace

TEST(Difficulty, AGoodPlayerBeatsTheEasyComputer)
{
    EXPECT_EQ(matchesWonByThePlayer(Difficulty::Easy, goodPlayer, 5), 5);
}

TEST(Difficulty, TheHardComputerBeatsAWeakPlayer)
{
    EXPECT_EQ(matchesWonByThePlayer(Difficulty::Hard, weakPlayer, 5), 0);
}

// Measured (seeds 100-102): the weak player against Easy 8-11, 11-10, 10-11; the decent
// player against Hard 11-6, 10-11, 11-5. Each difficulty can be beaten and can win.
TEST(Difficulty, TheEasyComputerIsAnEvenMatchForAWeakPlayer)
{
    const int won = matchesWonByThePlayer(Difficulty::Easy, weakPlayer, 3);
    EXPECT_GE(won, 1);
    EXPECT_LE(won, 2);
}

TEST(Difficulty, TheHardComputerIsAnEvenMatchForADecentPlayer)
{
    const int won = matchesWonByThePlayer(Difficulty::Hard, DecentPlayer(), 3);
    EXPECT_GE(won, 1);
    EXPECT_LE(won, 2);
}

TEST(Difficulty, ADecentPlayerBeatsTheNormalComputer)
{
    EXPECT_EQ(matchesWonByThePlayer(Difficulty::Normal, DecentPlayer(), 3), 3);
}

TEST(Difficulty, NamesReadBackAndUnknownNamesAreRefused)
{
    for (Difficulty difficulty : {Difficulty::Easy, Difficulty::Normal, Difficulty::Hard})
        EXPECT_EQ(difficultyFromName(nameOf(difficulty)), difficulty);
    EXPECT_THROW(difficultyFromName("impossible"), std::invalid_argument);
}
