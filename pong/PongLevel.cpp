#include "PongLevel.h"

#include "Sounds.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Keys.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

std::string nameOf(Mode mode)
{
    switch (mode)
    {
    case Mode::TwoPlayers:
        return "2p";
    case Mode::ComputerVsComputer:
        return "cvc";
    default:
        return "1p";
    }
}

Mode modeFromName(const std::string& name)
{
    for (Mode mode : {Mode::OnePlayer, Mode::TwoPlayers, Mode::ComputerVsComputer})
        if (nameOf(mode) == name)
            return mode;
    throw std::invalid_argument("--mode must be 1p, 2p or cvc, not '" + name + "'");
}

namespace
{
bool anyPlayerKeyPressed(const hitbox::Input& input)
{
    // The framework's own keys never count as "a player pressed something".
    for (int key = 0; key < hitbox::keyCount; ++key)
        if (!hitbox::isSharedKey(key) && input.isPressed(key))
            return true;
    return false;
}

float keyAxis(const hitbox::Input& input, sf::Keyboard::Key upKey, sf::Keyboard::Key downKey)
{
    return (input.isKeyDown(downKey) ? 1.f : 0.f) - (input.isKeyDown(upKey) ? 1.f : 0.f);
}

const int maxPointsToWin = 99;
} // namespace

PongState::PongState(const PongSettings& pongSettings)
    : settings(pongSettings), arena(), ball(), leftPaddle(-1, arena), rightPaddle(+1, arena),
      // Each computer player has its own random numbers, so one player's choices never
      // shift the other's.
      leftComputer(settings.difficulty, settings.seed * 2u + 1u),
      rightComputer(settings.difficulty, settings.seed * 2u + 2u), score(settings.pointsToWin),
      random(settings.seed), mode(settings.mode)
{
}

PongLevel::PongLevel(const PongSettings& pongSettings) : PongState(pongSettings)
{
    ball.placeAt({arena.centerX(), arena.centerY()});
    ballStepStart = ball.getPosition();
    // Names for the debugger's words (explain, the --timeline file).
    ball.setName("ball");
    leftPaddle.setName("left paddle");
    rightPaddle.setName("right paddle");
}

PongLevel::~PongLevel() = default;

void PongLevel::enableSound()
{
    if (!sounds)
        sounds = std::make_unique<Sounds>();
}

void PongLevel::showTitle()
{
    screen = Screen::Title;
    attractMode = false;
    idleSeconds = 0.f;
    leftIntent = rightIntent = 0.f;
    leftPaddle.placeAtStart(arena);
    rightPaddle.placeAtStart(arena);
    ball.placeAt({arena.centerX(), arena.centerY()});
}

void PongLevel::startMatch(Mode newMode)
{
    mode = newMode;
    screen = Screen::Play;
    score = Score(settings.pointsToWin);
    leftComputer = Opponent(settings.difficulty, settings.seed * 2u + 1u + 2u * matchesFinished);
    rightComputer = Opponent(settings.difficulty, settings.seed * 2u + 2u + 2u * matchesFinished);
    leftIntent = rightIntent = 0.f;
    leftPaddle.placeAtStart(arena);
    rightPaddle.placeAtStart(arena);
    // The first serve goes to a random side; after that, to whoever lost the point.
    prepareServe(random() % 2u == 0u ? Side::Left : Side::Right);
}

void PongLevel::startAttractMode()
{
    startMatch(Mode::ComputerVsComputer);
    attractMode = true;
}

void PongLevel::showWinScreen(int leftPoints, int rightPoints)
{
    score = Score(settings.pointsToWin);
    // The loser's points first: once the winner reaches the target, points stop counting.
    const Side loser = leftPoints < rightPoints ? Side::Left : Side::Right;
    const Side winner = opponentOf(loser);
    const int loserPoints = loser == Side::Left ? leftPoints : rightPoints;
    for (int i = 0; i < loserPoints; ++i)
        score.addPoint(loser);
    for (int i = 0; i < leftPoints + rightPoints - loserPoints; ++i)
        score.addPoint(winner);
    screen = Screen::Win;
    secondsOnWinScreen = 0.f;
    ball.placeAt({arena.centerX(), arena.centerY()});
}

void PongLevel::placeBall(sf::Vector2f position, sf::Vector2f velocity)
{
    ball.placeAt(position);
    ball.setVelocity(velocity);
    serveSecondsLeft = 0.f;
    ballStepStart = position;
}

bool PongLevel::isComputer(Side side) const
{
    if (mode == Mode::ComputerVsComputer)
        return true;
    return mode == Mode::OnePlayer && side == Side::Right;
}

void PongLevel::handleTitleKeys(const hitbox::Input& input)
{
    if (input.isPressed(sf::Keyboard::Key::Num1) || input.isPressed(sf::Keyboard::Key::Numpad1) ||
        input.isPressed(sf::Keyboard::Key::Enter) || input.isPressed(sf::Keyboard::Key::Space))
        startMatch(Mode::OnePlayer);
    else if (input.isPressed(sf::Keyboard::Key::Num2) ||
             input.isPressed(sf::Keyboard::Key::Numpad2))
        startMatch(Mode::TwoPlayers);
    else if (input.isPressed(sf::Keyboard::Key::Num3) ||
             input.isPressed(sf::Keyboard::Key::Numpad3))
        startMatch(Mode::ComputerVsComputer);
    else if (input.isPressed(sf::Keyboard::Key::D))
    {
        settings.difficulty = nextDifficulty(settings.difficulty);
        leftComputer = Opponent(settings.difficulty, settings.seed * 2u + 1u);
        rightComputer = Opponent(settings.difficulty, settings.seed * 2u + 2u);
    }
    else if (input.isPressed(sf::Keyboard::Key::Left) && settings.pointsToWin > 1)
        --settings.pointsToWin;
    else if (input.isPressed(sf::Keyboard::Key::Right) && settings.pointsToWin < maxPointsToWin)
        ++settings.pointsToWin;
}

void PongLevel::handleInput(const hitbox::Input& input, float)
{
    const bool playerPressedAKey = anyPlayerKeyPressed(input);
    if (input.isPressed(sf::Keyboard::Key::M))
        muted = !muted;

    if (screen == Screen::Title)
    {
        if (playerPressedAKey)
            idleSeconds = 0.f;
        handleTitleKeys(input);
        return;
    }
    if (attractMode)
    {
        // Anyone touching the keyboard wants to play: back to the menu.
        if (playerPressedAKey)
            showTitle();
        return;
    }
    if (screen == Screen::Win)
    {
        if (input.isPressed(sf::Keyboard::Key::Space) || input.isPressed(sf::Keyboard::Key::Enter))
            startMatch(mode);
        return;
    }
    if (mode == Mode::OnePlayer)
    {
        // One player: either pair of keys moves your (left) paddle.
        const float wasd = keyAxis(input, sf::Keyboard::Key::W, sf::Keyboard::Key::S);
        const float arrows = keyAxis(input, sf::Keyboard::Key::Up, sf::Keyboard::Key::Down);
        leftIntent = wasd != 0.f ? wasd : arrows;
    }
    else if (mode == Mode::TwoPlayers)
    {
        leftIntent = keyAxis(input, sf::Keyboard::Key::W, sf::Keyboard::Key::S);
        rightIntent = keyAxis(input, sf::Keyboard::Key::Up, sf::Keyboard::Key::Down);
    }
}

void PongLevel::update(float dt)
{
    ++stepCount;
    leftStepStart = leftPaddle.getPosition();
    rightStepStart = rightPaddle.getPosition();
    events.clear();
    secondsSinceContact += dt;
    if (screen == Screen::Title)
    {
        idleSeconds += dt;
        if (idleSeconds >= settings.idleSecondsBeforeAttract)
            startAttractMode();
    }
    else if (screen == Screen::Win)
    {
        secondsOnWinScreen += dt;
        // Computer against computer goes on by itself (an attract loop, or an hour-long
        // --headless run); people choose when to play again.
        if (mode == Mode::ComputerVsComputer && secondsOnWinScreen >= settings.secondsBeforeRematch)
        {
            const bool wasAttract = attractMode;
            startMatch(Mode::ComputerVsComputer);
            attractMode = wasAttract;
        }
    }
    else
        playStep(dt);

    if (sounds && !muted)
        sounds->play(events);
}

void PongLevel::playStep(float dt)
{
    // 1. Who wants to go where. Humans set their intent in handleInput.
    if (isComputer(Side::Left))
        leftIntent = leftComputer.decide(ball, leftPaddle, arena, dt);
    if (isComputer(Side::Right))
        rightIntent = rightComputer.decide(ball, rightPaddle, arena, dt);
    leftPaddle.planMove(leftIntent, arena, dt);
    rightPaddle.planMove(rightIntent, arena, dt);

    // 2. The ball: waiting to be served, or swept along its path.
    ballStepStart = ball.getPosition();
    if (serveSecondsLeft > 0.f)
    {
        serveSecondsLeft -= dt;
        if (serveSecondsLeft <= 0.f)
            serve();
    }
    else
    {
        const BallStep step = moveBall(ball, leftPaddle, rightPaddle, arena, dt);
        for (GameEvent event : step.events)
        {
            events.push_back(event);
            if (event == GameEvent::PaddleHit)
                ++paddleHitsTotal;
        }
        if (step.lastHit.hit)
        {
            lastHit = step.lastHit;
            secondsSinceContact = 0.f;
        }
    }

    // 3. The paddles finish their move (never into the ball).
    leftPaddle.finishMove(ball.getCollisionBox());
    rightPaddle.finishMove(ball.getCollisionBox());

    // 4. Out of the arena at a side: a point. (Never true with a finite position inside;
    // a non-finite one would be a bug, so it restarts the rally rather than vanish.)
    const hitbox::Box ballBox = hitbox::toBox(ball.getCollisionBox());
    if (!hitbox::isFinite(ballBox) || !hitbox::isFinite(hitbox::toVec2(ball.getVelocity())))
        prepareServe(serveSide);
    else if (hitbox::rightOf(ballBox) < 0.f)
        scorePoint(Side::Right);
    else if (ballBox.left > arena.size.x)
        scorePoint(Side::Left);
}

void PongLevel::finishMatch()
{
    events.push_back(GameEvent::MatchWon);
    ++matchesFinished;
    ++(score.getWinner() == Side::Left ? leftMatchesWon : rightMatchesWon);
    screen = Screen::Win;
    secondsOnWinScreen = 0.f;
    ball.placeAt({arena.centerX(), arena.centerY()});
}

// [slide:pong-serve]
void PongLevel::scorePoint(Side scorer)
{
    score.addPoint(scorer);
    events.push_back(GameEvent::Point);
    if (score.isMatchOver())
        finishMatch();
    else
        prepareServe(Score::serveTowards(scorer)); // towards the player who lost the point
}

void PongLevel::prepareServe(Side towards)
{
    // The ball waits in the middle for a moment, so the receiver can get ready.
    ball.placeAt({arena.centerX(), arena.centerY()});
    serveSide = towards;
    serveSecondsLeft = settings.serveDelaySeconds;
}

void PongLevel::serve() // called when the wait is over
{
    const float unit = static_cast<float>(random() % 1000001u) / 1000000.f; // 0..1
    const float degrees = (2.f * unit - 1.f) * settings.maxServeDegrees;
    ball.serve(directionOf(serveSide), degrees);
}
// [/slide]

bool PongLevel::handleEscape()
{
    if (screen == Screen::Title)
        return false; // Esc on the title quits the program
    showTitle();
    return true;
}

sf::Vector2f PongLevel::getWorldSize() const
{
    return arena.size;
}

std::string PongLevel::getHelpText() const
{
    if (screen == Screen::Title)
        return "1/2/3 mode   D difficulty   Left/Right points   M mute";
    if (attractMode)
        return "any key: menu";
    if (screen == Screen::Win)
        return "Space rematch   Esc menu   M mute";
    if (mode == Mode::OnePlayer)
        return "W/S or Up/Down move   M mute   Esc menu";
    if (mode == Mode::TwoPlayers)
        return "left W/S   right Up/Down   M mute   Esc menu";
    return "M mute   Esc menu";
}

std::string PongLevel::describeState() const
{
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(2);
    text << "mode " << nameOf(mode) << " " << nameOf(settings.difficulty) << " | matches won left "
         << leftMatchesWon << " right " << rightMatchesWon << " | score "
         << score.pointsOf(Side::Left) << "-" << score.pointsOf(Side::Right) << " (first to "
         << score.getPointsToWin() << ") | paddle hits " << paddleHitsTotal << " | steps "
         << stepCount << " | ball " << ball.getPosition().x << "," << ball.getPosition().y;
    return text.str();
}

Screen PongLevel::getScreen() const
{
    return screen;
}

Mode PongLevel::getMode() const
{
    return mode;
}

Difficulty PongLevel::getDifficulty() const
{
    return settings.difficulty;
}

bool PongLevel::isAttractMode() const
{
    return attractMode;
}

bool PongLevel::isServing() const
{
    return screen == Screen::Play && serveSecondsLeft > 0.f;
}

Side PongLevel::getServeSide() const
{
    return serveSide;
}

bool PongLevel::isMuted() const
{
    return muted;
}

const Score& PongLevel::getScore() const
{
    return score;
}

const Ball& PongLevel::getBall() const
{
    return ball;
}

const Paddle& PongLevel::getPaddle(Side side) const
{
    return side == Side::Left ? leftPaddle : rightPaddle;
}

const Arena& PongLevel::getArena() const
{
    return arena;
}

const std::vector<GameEvent>& PongLevel::getEvents() const
{
    return events;
}

long long PongLevel::getStepCount() const
{
    return stepCount;
}

int PongLevel::getMatchesFinished() const
{
    return matchesFinished;
}

int PongLevel::getMatchesWon(Side side) const
{
    return side == Side::Left ? leftMatchesWon : rightMatchesWon;
}

long long PongLevel::getPaddleHitsTotal() const
{
    return paddleHitsTotal;
}
