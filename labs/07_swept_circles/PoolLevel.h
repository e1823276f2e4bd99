// PoolLevel.h - a pool table whose collisions are found by TIME OF IMPACT.
//
// Each step asks: of everything that could happen during this step (a ball hitting a ball,
// a ball hitting a cushion), what happens FIRST, and when? Every ball moves up to that moment,
// that one collision is answered, and the rest of the step is simulated the same way. Because
// the sweeps look at the whole move, a ball at any speed hits the ball in its way instead of
// jumping over it (swept circles: Ericson, Real-Time Collision Detection, 5.5).
// Press D for the discrete version (move, then look for overlaps) to see the difference.
#pragma once

#include "Ball.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"
#include "hitbox/geometry/Sweep.h"

#include <cstddef>
#include <memory>
#include <vector>

// The first collision of the rest of a step.
struct BallEvent
{
    bool hit = false;
    float time = 1.f;       // fraction of the time being searched, 0..1
    std::size_t first = 0;  // a ball
    std::size_t second = 0; // another ball (ball-ball events only)
    int cushion = -1;       // >= 0: `first` hits this cushion instead of a ball
    hitbox::Vec2 normal;    // out of what was hit, towards `first`
};

// An impact, remembered for the picture: both balls where they touched.
struct Impact
{
    hitbox::Circle first;
    hitbox::Circle second;
    hitbox::Vec2 normal;
};

class PoolLevel : public hitbox::Level
{
public:
    // The lab's table: ten balls racked, the cue ball already on its way at break speed.
    PoolLevel();
    // Any balls on a table whose playing area (inside the cushions) is `table`.
    PoolLevel(std::vector<Ball> balls, hitbox::Box table);

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    // The window's rewind (hitbox::RewindLevel): a copy of the whole level, which is all
    // values, so a field added to it is rewound too. Without it the rewind re-simulates from
    // the start, and a step of this lab is slow enough for that to show.
    std::unique_ptr<hitbox::LevelState> saveState() const override;
    void restoreState(const hitbox::LevelState& state) override;
    std::string describeState() const override;

    // Task 1 (and task 3): the earliest collision if every ball moves by velocity * seconds.
    BallEvent findFirstEvent(float seconds) const;
    // Task 2: the velocities of two equal balls after they bump along `normal` (unit, out of
    // the second towards the first). Returns {first, second}.
    static std::pair<hitbox::Vec2, hitbox::Vec2>
    bounceBalls(hitbox::Vec2 first, hitbox::Vec2 second, hitbox::Vec2 normal);

    // A sweep's hit is a new collision unless the two already overlap and are moving apart
    // (`relativeVelocity`: the mover's velocity minus the target's).
    static bool isNewCollision(const hitbox::Hit& hit, hitbox::Vec2 relativeVelocity);

    // true: time of impact (the lab); false: discrete (move, then push overlaps apart).
    void setSwept(bool on);
    void setFriction(bool on);
    // Send the cue ball (ball 0) towards `target` at `speed` pixels per second.
    void shoot(hitbox::Vec2 target, float speed);

    const std::vector<Ball>& getBalls() const;
    const std::vector<hitbox::Box>& getCushions() const;
    hitbox::Box getTable() const;

private:
    void stepSwept(float dt);
    void stepDiscrete(float dt);
    void answer(const BallEvent& event);

    std::vector<Ball> balls;
    hitbox::Box table;
    std::vector<hitbox::Box> cushions;
    bool swept = true;
    bool friction = true;
    float shotSpeed = 6000.f;
    hitbox::Vec2 mouse;
    std::vector<hitbox::Vec2> cueTrail; // the cue ball after each step
    std::vector<Impact> impacts;        // the latest ball-ball impacts
    struct CueImpact
    {
        bool happened = false;
        hitbox::Vec2 where;       // the cue ball's centre when it touched
        float stepFraction = 0.f; // when, as a fraction of that whole step
    } cueImpact;                  // the cue ball's latest ball-ball impact
    hitbox::LazyFont font;        // read by the first render(): tests need no font file
};
