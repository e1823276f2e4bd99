// PongSnapshot.cpp - Pong's state as a value, so the paused window can step back through the
// last 10 seconds (hitbox::RewindLevel, framework/hitbox/app/Rewind.h); and its paddle hits as
// contact events for the rewind strip. Not saved: the font and the sounds (nothing a rule reads).
#include "PongLevel.h"

#include <utility>

namespace
{

// A PongLevel's members, by value: the copy the level takes of itself.
struct PongState : hitbox::LevelState
{
    PongState(const PongSettings& settings, const Paddle& left, const Paddle& right)
        : settings(settings), leftPaddle(left), rightPaddle(right), score(settings.pointsToWin)
    {
    }

    std::size_t bytes() const override
    {
        return sizeof(PongState) + events.capacity() * sizeof(GameEvent);
    }

    PongSettings settings;
    Arena arena;
    Ball ball;
    Paddle leftPaddle;
    Paddle rightPaddle;
    Opponent leftComputer{Difficulty::Normal, 0};
    Opponent rightComputer{Difficulty::Normal, 0};
    Score score;
    std::mt19937 random;
    Screen screen = Screen::Title;
    Mode mode = Mode::OnePlayer;
    bool attractMode = false;
    bool muted = false;
    float leftIntent = 0.f;
    float rightIntent = 0.f;
    float serveSecondsLeft = 0.f;
    Side serveSide = Side::Left;
    float idleSeconds = 0.f;
    float secondsOnWinScreen = 0.f;
    float secondsSinceContact = 0.f;
    std::vector<GameEvent> events;
    hitbox::Hit lastHit;
    sf::Vector2f ballStepStart;
    sf::Vector2f leftStepStart;
    sf::Vector2f rightStepStart;
    long long stepCount = 0;
    int matchesFinished = 0;
    int leftMatchesWon = 0;
    int rightMatchesWon = 0;
    long long paddleHitsTotal = 0;
};

} // namespace

std::unique_ptr<hitbox::LevelState> PongLevel::saveState() const
{
    auto saved = std::make_unique<PongState>(settings, leftPaddle, rightPaddle);
    saved->settings = settings;
    saved->arena = arena;
    saved->ball = ball;
    saved->leftPaddle = leftPaddle;
    saved->rightPaddle = rightPaddle;
    saved->leftComputer = leftComputer;
    saved->rightComputer = rightComputer;
    saved->score = score;
    saved->random = random;
    saved->screen = screen;
    saved->mode = mode;
    saved->attractMode = attractMode;
    saved->muted = muted;
    saved->leftIntent = leftIntent;
    saved->rightIntent = rightIntent;
    saved->serveSecondsLeft = serveSecondsLeft;
    saved->serveSide = serveSide;
    saved->idleSeconds = idleSeconds;
    saved->secondsOnWinScreen = secondsOnWinScreen;
    saved->secondsSinceContact = secondsSinceContact;
    saved->events = events;
    saved->lastHit = lastHit;
    saved->ballStepStart = ballStepStart;
    saved->leftStepStart = leftStepStart;
    saved->rightStepStart = rightStepStart;
    saved->stepCount = stepCount;
    saved->matchesFinished = matchesFinished;
    saved->leftMatchesWon = leftMatchesWon;
    saved->rightMatchesWon = rightMatchesWon;
    saved->paddleHitsTotal = paddleHitsTotal;
    return saved;
}

void PongLevel::restoreState(const hitbox::LevelState& state)
{
    const PongState& saved = static_cast<const PongState&>(state);
    settings = saved.settings;
    arena = saved.arena;
    ball = saved.ball;
    leftPaddle = saved.leftPaddle;
    rightPaddle = saved.rightPaddle;
    leftComputer = saved.leftComputer;
    rightComputer = saved.rightComputer;
    score = saved.score;
    random = saved.random;
    screen = saved.screen;
    mode = saved.mode;
    attractMode = saved.attractMode;
    muted = saved.muted;
    leftIntent = saved.leftIntent;
    rightIntent = saved.rightIntent;
    serveSecondsLeft = saved.serveSecondsLeft;
    serveSide = saved.serveSide;
    idleSeconds = saved.idleSeconds;
    secondsOnWinScreen = saved.secondsOnWinScreen;
    secondsSinceContact = saved.secondsSinceContact;
    events = saved.events;
    lastHit = saved.lastHit;
    ballStepStart = saved.ballStepStart;
    leftStepStart = saved.leftStepStart;
    rightStepStart = saved.rightStepStart;
    stepCount = saved.stepCount;
    matchesFinished = saved.matchesFinished;
    leftMatchesWon = saved.leftMatchesWon;
    rightMatchesWon = saved.rightMatchesWon;
    paddleHitsTotal = saved.paddleHitsTotal;
}

std::vector<hitbox::PairEvent> PongLevel::getContactEvents() const
{
    std::vector<hitbox::PairEvent> contacts;
    for (GameEvent event : events)
    {
        if (event != GameEvent::PaddleHit)
            continue;
        // The paddle on the ball's side of the net is the one it bounced off.
        const Paddle& paddle = ball.getPosition().x < arena.centerX() ? leftPaddle : rightPaddle;
        for (hitbox::ContactPhase phase : {hitbox::ContactPhase::Enter, hitbox::ContactPhase::Exit})
        {
            hitbox::PairEvent contact;
            contact.phase = phase;
            contact.first = const_cast<Ball*>(&ball);
            contact.second = const_cast<Paddle*>(&paddle);
            contact.contact = lastHit.hit
                                  ? hitbox::Contact{true, lastHit.normal, 0.f, lastHit.point}
                                  : hitbox::Contact{};
            contact.step = static_cast<std::uint64_t>(stepCount);
            contacts.push_back(contact);
        }
    }
    return contacts;
}
