// PaperLevel.h - a shooting range with one sheet of paper (a 4-pixel wall).
//
// Every shot fires two identical bullets at the same speed: the top one is tested the
// discrete way (where is it after the step?), the bottom one the swept way (what did the
// whole step cover?). Shots get faster and faster; the scoreboard counts hits and misses.
#pragma once

#include "Bullet.h"

#include "hitbox/app/Assets.h"
#include "hitbox/app/Level.h"

#include <memory>

struct LaneScore
{
    int hits = 0;
    int misses = 0;
};

class PaperLevel : public hitbox::Level
{
public:
    PaperLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;

    // Fire one shot (a bullet in each lane) at `speed` pixels per second, now.
    void fire(float speed);
    // Auto-fire (on at the start): a new, faster shot once the last one is done.
    void setAutoFire(bool on);
    // The speed the next automatic shot will have.
    float getNextSpeed() const;

    // The current shot's bullet in a lane (nullptr before the first shot).
    const Bullet* getBullet(Lane lane) const;
    LaneScore getScore(Lane lane) const;
    const hitbox::Box& getWall() const;

    // Task 3: could a move of `step` (one step, in pixels) carry this bullet right through
    // the wall without a discrete test ever seeing them overlap?
    bool stepCouldTunnel(const Bullet& bullet, sf::Vector2f step) const;

private:
    void stepDiscrete(Bullet& bullet, sf::Vector2f step);
    void stepSwept(Bullet& bullet, sf::Vector2f step);
    void updateBullet(Bullet& bullet, float dt);
    void drawLane(sf::RenderTarget& target, Lane lane) const;
    void drawJumpOverWall(sf::RenderTarget& target, const Bullet& bullet) const;

    hitbox::Box wall;
    std::unique_ptr<Bullet> discreteBullet;
    std::unique_ptr<Bullet> sweptBullet;
    LaneScore discreteScore;
    LaneScore sweptScore;
    bool autoFire = true;
    float nextSpeed;
    float secondsUntilNextShot = 0.f;
    int shotsFired = 0;
    hitbox::LazyFont font; // read by the first render(): tests need no font file
};
