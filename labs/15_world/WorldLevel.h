// WorldLevel.h - a player, coins and wandering enemies, all in one hitbox::World.
//
// The level owns the objects (each in a unique_ptr, so its address never changes); the
// World only points at them and, once a step, finds every pair that collides.
#pragma once

#include "Pieces.h"
#include "Rules.h"

#include "hitbox/app/Level.h"
#include "hitbox/objects/World.h"

#include <memory>
#include <random>
#include <string>
#include <vector>

// How many coins and enemies a new level has.
constexpr int startCoins = 14;
constexpr int startEnemies = 7;

class WorldLevel : public hitbox::Level
{
public:
    // Coins and enemies in random places from `seed`; the player in the middle, on autopilot.
    explicit WorldLevel(unsigned seed = 1);

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;
    std::vector<hitbox::PairEvent> getContactEvents() const override;

    // For the grading tests (and for experiments): set up any scene you like.
    // Removes every coin and enemy; the player stays, still, with autopilot off.
    void removeAllButThePlayer();
    void addCoin(sf::Vector2f center);
    void addEnemy(sf::Vector2f center, sf::Vector2f velocity);
    void placePlayer(sf::Vector2f center);
    void setAutopilot(bool on);

    const Player& getPlayer() const;
    int getCoinCount() const;
    const Coin& getCoin(int index) const;
    int getEnemyCount() const;
    const Enemy& getEnemy(int index) const;
    int getScore() const;
    const hitbox::World& getWorld() const;

private:
    void start();
    void addRandomCoin();
    void addRandomEnemy();
    void wander(float dt);
    void steerPlayer(const hitbox::Input& input);

    std::mt19937 random;
    sf::Vector2f mouse; // world coordinates: F1 explains the pair under it
    hitbox::World world;
    std::unique_ptr<Player> player;
    std::vector<std::unique_ptr<Coin>> coins;
    std::vector<std::unique_ptr<Enemy>> enemies;
    int score = 0;
    bool autopilot = true;
    bool newWaves = true; // all coins taken: a new wave (not in the tests' scenes)
    float turnClock = 0.f;
};
