// Opponent.h - the computer player: decides which way its paddle should move.
//
// It sees exactly what a person sees (where the ball is and where it is going) and plays
// with human flaws whose size the difficulty sets: it reacts late, it misjudges where the
// ball will arrive, its paddle is slower, and only the better players work out the bounce
// off a wall in advance. It returns an "intent" from -1 (up) to +1 (down) like the keys do.
#pragma once

#include "Arena.h"
#include "Ball.h"
#include "Paddle.h"

#include <random>
#include <string>

enum class Difficulty
{
    Easy,
    Normal,
    Hard
};

std::string nameOf(Difficulty difficulty); // "easy", "normal", "hard"
// Reads "easy" / "normal" / "hard"; throws std::invalid_argument otherwise.
Difficulty difficultyFromName(const std::string& name);
Difficulty nextDifficulty(Difficulty difficulty); // Easy -> Normal -> Hard -> Easy

struct OpponentSkill
{
    float reactionSeconds; // how long between looks at the ball
    float topSpeed;        // fraction of the paddle's full speed it uses
    float aimError;        // how far off its guess of the arrival point may be: pixels
                           // at serve speed, growing with the speed of the ball
    bool readsBounces;     // works out where the ball arrives after bouncing off walls
};

OpponentSkill skillFor(Difficulty difficulty);

class Opponent
{
public:
    Opponent(Difficulty difficulty, unsigned seed);

    // Which way to move the paddle this step.
    float decide(const Ball& ball, const Paddle& paddle, const Arena& arena, float dt);

    Difficulty getDifficulty() const;
    float getTargetY() const; // where it is heading (for the debug view)

private:
    float predictArrivalY(const Ball& ball, const Paddle& paddle, const Arena& arena) const;
    float randomBetween(float low, float high);

    Difficulty difficulty;
    OpponentSkill skill;
    std::mt19937 random; // seeded: the same seed plays the same match
    float secondsUntilNextLook = 0.f;
    float targetY = -1.f; // -1: no target yet
    float aimOffset = 0.f;
    bool wasComingTowardsMe = false;
};
