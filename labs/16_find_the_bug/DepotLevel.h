// DepotLevel.h - a depot with two belts of crates, all in one hitbox::World. A crate on the
// upper belt crosses a pressure plate, which opens the gate on the lower belt; the gate
// closes once the plate lets go and nothing is in its gateway; both belts end in the drop
// zone, where crates are delivered and taken away. The gatekeeper (arrow keys) stands on top
// of the gate post. No randomness: the same keys at the same steps give the same run.
#pragma once

#include "Bugs.h"
#include "Pieces.h"

#include "hitbox/app/Level.h"
#include "hitbox/objects/World.h"

#include <memory>
#include <string>
#include <vector>

// Where things are (world pixels, in the world of hitbox::defaultWorldSize) and how often the
// belts bring a crate.
constexpr float upperBeltTop = 160.f; // the top of the upper belt's crates
constexpr float lowerBeltTop = 440.f; // the top of the lower belt's crates
const hitbox::Box plateBox{480.f, 150.f, 160.f, 60.f};
const hitbox::Box gatewayBox{640.f, 420.f, 20.f, 80.f};
const sf::Vector2f guardStart{630.f, 380.f}; // on the gate post: touches the gateway's top
const hitbox::Box dropZoneBox{1100.f, 120.f, 60.f, 420.f};
constexpr int upperBeltSteps = 360; // a crate every 3 s on the upper belt
constexpr int lowerBeltSteps = 240; // and every 2 s on the lower one

class DepotLevel : public hitbox::Level
{
public:
    DepotLevel();

    void handleInput(const hitbox::Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderDebug(hitbox::DebugRenderer& debug) const override;
    std::string getHelpText() const override;
    std::string describeState() const override;
    std::vector<hitbox::PairEvent> getContactEvents() const override;

    // For the grading tests.
    [[nodiscard]] const PressurePlate& getPlate() const;
    [[nodiscard]] const hitbox::GameObject& getGuard() const;
    [[nodiscard]] const hitbox::GameObject& getGateway() const;
    [[nodiscard]] int getCrateCount() const;
    [[nodiscard]] const Crate& getCrate(int index) const;
    [[nodiscard]] int getDelivered() const;
    [[nodiscard]] bool isGateOpen() const;
    // No crate and no gatekeeper in the gateway (inGateway, task 2).
    [[nodiscard]] bool isGatewayClear() const;
    [[nodiscard]] const hitbox::World& getWorld() const;

private:
    void start();
    void spawnCrates();
    void moveCrates(float dt);

    hitbox::World world;
    std::unique_ptr<PressurePlate> plate;
    std::unique_ptr<Piece> gateway;
    std::unique_ptr<Piece> dropZone;
    std::unique_ptr<Piece> guard;
    std::vector<std::unique_ptr<Crate>> crates;
    sf::Vector2f guardDirection;
    sf::Vector2f mouse; // world coordinates: F1 explains the pair under it
    long long steps = 0;
    int cratesMade = 0;
    int delivered = 0;
    bool gateOpen = false;
};
