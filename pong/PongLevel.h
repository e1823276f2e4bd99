// PongLevel.h - the whole game: screens, modes, serving, scoring, and who steers each paddle.
//
// Screens: Title (choose a mode) -> Play -> Win -> Play again or back to the Title. Left
// alone on the title for a while, the game plays itself (attract mode) until a key is
// pressed. Every rule runs in update(); render() (PongView.cpp) only draws the state, and
// the events of each step go to the sound layer, so tests run a whole match with no window.
#pragma once

#include "Arena.h"
#include "Ball.h"
#include "BallPhysics.h"
#include "GameEvents.h"
#include "Opponent.h"
#include "Paddle.h"
#include "Score.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"

#include <memory>
#include <random>
#include <string>
#include <vector>

class Sounds;

enum class Screen
{
    Title,
    Play,
    Win
};

enum class Mode
{
    OnePlayer,         // you (left paddle) against the computer
    TwoPlayers,        // W/S against Up/Down
    ComputerVsComputer // the computer plays both paddles
};

std::string nameOf(Mode mode); // "1p", "2p", "cvc" (the --mode values)
// Reads the --mode values; throws std::invalid_argument otherwise.
Mode modeFromName(const std::string& name);

struct PongSettings
{
    Mode mode = Mode::OnePlayer;
    Difficulty difficulty = Difficulty::Normal;
    int pointsToWin = 11;
    unsigned seed = 1;
    float idleSecondsBeforeAttract = 15.f; // on the title screen
    float serveDelaySeconds = 1.f;         // pause before each serve
    float maxServeDegrees = 30.f;          // serves go out at a random angle up to this
    float secondsBeforeRematch = 4.f;      // computer vs computer: next match starts by itself
};

// Everything a step changes, in one plain struct: saveState copies it whole and restoreState
// assigns it back (PongSnapshot.cpp), so a value added here is rewound without another line.
// What is not here (the font, the sounds) no rule reads.
struct PongState
{
    explicit PongState(const PongSettings& chosen);

    PongSettings settings;
    Arena arena;
    Ball ball;
    Paddle leftPaddle;
    Paddle rightPaddle;
    Opponent leftComputer;
    Opponent rightComputer;
    Score score;
    std::mt19937 random; // serve angles and the first server; seeded, so runs repeat

    Screen screen = Screen::Title;
    Mode mode = Mode::OnePlayer;
    bool attractMode = false;
    bool muted = false;
    float leftIntent = 0.f; // -1 up .. +1 down, from the keys or the computer
    float rightIntent = 0.f;
    float serveSecondsLeft = 0.f;
    Side serveSide = Side::Left;
    float idleSeconds = 0.f; // title screen: time since the last key
    float secondsOnWinScreen = 0.f;
    float secondsSinceContact = 99.f; // for the debug view's "touching" colour

    std::vector<GameEvent> events;
    hitbox::Hit lastHit;        // the ball's last contact, for the debug view
    sf::Vector2f ballStepStart; // where the ball began the last step (debug view)
    sf::Vector2f leftStepStart; // where the paddles began it (drawing between steps)
    sf::Vector2f rightStepStart;
    long long stepCount = 0;
    int matchesFinished = 0;
    int leftMatchesWon = 0;
    int rightMatchesWon = 0;
    long long paddleHitsTotal = 0;
};

// PongLevel inherits its state privately: the rules read `ball`, `score`... as plain members, and
// only the snapshot sees the whole.
class PongLevel : public hitbox::Level, private PongState
{
public:
    explicit PongLevel(const PongSettings& settings = {});
    ~PongLevel() override; // Sounds is only declared here

    // Switching screens (the keys do this; main.cpp and tests may too).
    void showTitle();
    void startMatch(Mode mode);
    void startAttractMode(); // computer vs computer, until any key is pressed
    void showWinScreen(int leftPoints, int rightPoints); // a finished match, e.g. for a picture
    // Put the ball somewhere with some velocity, mid-rally (tests and demonstrations).
    void placeBall(sf::Vector2f position, sf::Vector2f velocity);
    // Play sound effects from now on. Only for a program with a window (see Sounds.h).
    void enableSound();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    // The ball and paddles drawn `leftover` of a step past the step before (Level.h).
    void renderBlended(sf::RenderTarget& target, float leftover) const override;
    // A paddle hit as an enter and an exit in the same step (the swept ball touches the paddle
    // and leaves it within the step): what the window's rewind strip marks (Level.h).
    std::vector<hitbox::PairEvent> getContactEvents() const override;
    // Rewinding (Level.h, PongSnapshot.cpp): every value a step changes.
    std::unique_ptr<hitbox::LevelState> saveState() const override;
    void restoreState(const hitbox::LevelState& state) override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    sf::Vector2f getWorldSize() const override;
    std::string getHelpText() const override;
    std::string describeState() const override;
    bool handleEscape() override;

    // Read-only state, for render(), the sound layer and tests.
    Screen getScreen() const;
    Mode getMode() const;
    Difficulty getDifficulty() const;
    bool isAttractMode() const;
    bool isServing() const;    // the ball waits in the middle
    Side getServeSide() const; // who the next serve goes towards
    bool isMuted() const;
    const Score& getScore() const;
    const Ball& getBall() const;
    const Paddle& getPaddle(Side side) const;
    const Arena& getArena() const;
    const std::vector<GameEvent>& getEvents() const; // what happened in the last step
    long long getStepCount() const;
    int getMatchesFinished() const;
    int getMatchesWon(Side side) const;
    long long getPaddleHitsTotal() const;

private:
    bool isComputer(Side side) const;
    void handleTitleKeys(const hitbox::Input& input);
    void playStep(float dt);
    void prepareServe(Side towards);
    void serve();
    void scorePoint(Side scorer);
    void finishMatch();

    hitbox::LazyFont font;          // read by the first render(): tests need no font file
    std::unique_ptr<Sounds> sounds; // null: silent (headless runs, tests)
};
