// Grading tests of lab 16 (find the bug). Each suite is named after the task it checks;
// README.md lists them. No window: the World and the level run one fixed step at a time.
//
// Each task's tests reach only that task's code: task 1's build their own World with a plate,
// task 2's call inGateway alone or ask a level that has not stepped whether its gateway is
// clear, task 3's call removeDelivered on crates they marked, or check the program's own run
// for delivered crates, which only task 3 removes. A mistake in one task costs that task
// alone. (Only task 3 runs the program's scene: every step calls removeDelivered, so a
// removeDelivered that crashes would fail any test that steps the level.)
#include "labs/LabTesting.h"
#include "support/CollisionMatchers.h"
#include "support/SceneReplay.h"

#include "Bugs.h"
#include "DepotLevel.h"
#include "Pieces.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/objects/ExplainPair.h"
#include "hitbox/objects/World.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace
{

using hitbox::testing::Collides;
using hitbox::testing::NotCollides;
using hitbox::testing::Touches;
using Body = hitbox::World::Body;

const char* const programTitle = "Lab 16 - Find the bug";

// A plate with its top-left at (100, 100), 100 x 40, as a trigger in `world`.
struct PlateScene
{
    PlateScene() { world.add(plate, layer::zone, layer::crate, Shape::Box, Body::Trigger); }
    // A crate added to the World with its top-left at `topLeft`.
    Crate& addCrate(sf::Vector2f topLeft)
    {
        crates.push_back(std::make_unique<Crate>(topLeft));
        crates.back()->setName("crate " + std::to_string(crates.size()));
        world.add(*crates.back(), layer::crate, layer::zone);
        return *crates.back();
    }
    using Shape = hitbox::World::Shape;

    hitbox::World world;
    PressurePlate plate{{100.f, 100.f}, {100.f, 40.f}};
    std::vector<std::unique_ptr<Crate>> crates;
};

const sf::Vector2f onThePlate{130.f, 100.f};
const sf::Vector2f offThePlate{400.f, 100.f};

// A GameObject with `box` as its collision box, for the matchers and explain.
hitbox::GameObject objectAt(const hitbox::Box& box, const std::string& name)
{
    hitbox::GameObject object;
    object.setSize({box.width, box.height});
    object.setPosition({box.left, box.top});
    object.setName(name);
    return object;
}

} // namespace

TEST(Level, TheSameStepsGiveTheSameRun)
{
    DepotLevel first;
    DepotLevel second;
    hitbox::simulate(first, 1500);
    hitbox::simulate(second, 1500);
    EXPECT_EQ(first.describeState(), second.describeState());
    EXPECT_GT(first.getDelivered(), 0) << "crates reach the drop zone";
}

TEST(Level, TheGatekeeperStartsTouchingTheGateway)
{
    // The scene of task 2: the gatekeeper stands on the gate post, its bottom edge on the
    // gateway's top edge. Touching, so the World reports no collision.
    const DepotLevel level;
    EXPECT_THAT(level.getGuard(), Touches(level.getGateway()));
    EXPECT_THAT(level.getGuard(), NotCollides(level.getGateway()));
}

TEST(Task1PlateUsesEnterAndExit, ACrateOnThePlatePressesItAndLeavingLetsGo)
{
    PlateScene scene;
    Crate& crate = scene.addCrate(offThePlate);
    scene.world.checkCollisions();
    EXPECT_FALSE(scene.plate.isPressed()) << "nothing on the plate yet";
    crate.setPosition(onThePlate);
    ASSERT_THAT(crate, Collides(scene.plate));
    scene.world.checkCollisions();
    EXPECT_TRUE(scene.plate.isPressed()) << "a crate is on the plate";
    scene.world.checkCollisions();
    EXPECT_TRUE(scene.plate.isPressed()) << "the crate is still on the plate";
    crate.setPosition(offThePlate);
    scene.world.checkCollisions();
    EXPECT_FALSE(scene.plate.isPressed()) << "the crate left the plate (an Exit event)";
}

TEST(Task1PlateUsesEnterAndExit, ThePlateWorksAgainAfterACrateLeft)
{
    // An "already pressed" flag works once: the second crate must press the plate again.
    PlateScene scene;
    Crate& crate = scene.addCrate(onThePlate);
    scene.world.checkCollisions();
    crate.setPosition(offThePlate);
    scene.world.checkCollisions();
    ASSERT_FALSE(scene.plate.isPressed()) << "the first crate left the plate";
    crate.setPosition(onThePlate);
    scene.world.checkCollisions();
    EXPECT_TRUE(scene.plate.isPressed()) << "pressed again: the plate re-arms";
}

TEST(Task1PlateUsesEnterAndExit, TwoCratesKeepItPressedUntilBothLeave)
{
    PlateScene scene;
    Crate& first = scene.addCrate(onThePlate);
    Crate& second = scene.addCrate(onThePlate + sf::Vector2f{20.f, 0.f});
    scene.world.checkCollisions();
    first.setPosition(offThePlate);
    scene.world.checkCollisions();
    EXPECT_TRUE(scene.plate.isPressed()) << "one crate left, the other is still on the plate";
    second.setPosition(offThePlate + sf::Vector2f{100.f, 0.f});
    scene.world.checkCollisions();
    EXPECT_FALSE(scene.plate.isPressed()) << "both crates left";
}

TEST(Task1PlateUsesEnterAndExit, ACrateTakenAwayWhileOnThePlateLetsGo)
{
    // Removed from the World or destroyed while standing on the plate: the World still sends
    // the plate an Exit. No step of collisions would ever notice it otherwise.
    PlateScene scene;
    Crate& removed = scene.addCrate(onThePlate);
    scene.addCrate(onThePlate + sf::Vector2f{20.f, 0.f});
    scene.world.checkCollisions();
    scene.world.remove(removed);
    EXPECT_TRUE(scene.plate.isPressed()) << "one crate is still on the plate";
    scene.crates.back().reset(); // the other one is destroyed
    EXPECT_FALSE(scene.plate.isPressed()) << "nothing is left on the plate";
}

TEST(Task1PlateUsesEnterAndExit, ACrateOnlyTouchingThePlateDoesNotPressIt)
{
    // The World's rule: touching is not colliding, so no Enter.
    PlateScene scene;
    Crate& crate = scene.addCrate({200.f, 100.f}); // its left edge on the plate's right edge
    ASSERT_THAT(crate, Touches(scene.plate));
    scene.world.checkCollisions();
    EXPECT_FALSE(scene.plate.isPressed());
}

TEST(Task2TouchingIsNotInTheGateway, TouchingOnEachSideIsNotIn)
{
    const hitbox::Box gateway{640.f, 420.f, 20.f, 80.f};
    const hitbox::GameObject door = objectAt(gateway, "gateway");
    const hitbox::Box sides[] = {{600.f, 440.f, 40.f, 40.f},  // left of it
                                 {660.f, 440.f, 40.f, 40.f},  // right
                                 {630.f, 380.f, 40.f, 40.f},  // on top (the gatekeeper)
                                 {630.f, 500.f, 40.f, 40.f},  // below
                                 {600.f, 380.f, 40.f, 40.f}}; // corner to corner
    for (const hitbox::Box& side : sides)
    {
        const hitbox::GameObject thing = objectAt(side, "thing");
        ASSERT_THAT(thing, Touches(door));
        EXPECT_FALSE(inGateway(gateway, side)) << "it only touches the gateway; explain says:\n"
                                               << hitbox::toText(hitbox::explain(thing, door));
    }
}

TEST(Task2TouchingIsNotInTheGateway, OverlappingOnEachSideIsIn)
{
    const hitbox::Box gateway{640.f, 420.f, 20.f, 80.f};
    const hitbox::GameObject door = objectAt(gateway, "gateway");
    const hitbox::Box sides[] = {{601.f, 440.f, 40.f, 40.f},   // 1 pixel in from the left
                                 {659.5f, 440.f, 40.f, 40.f},  // half a pixel from the right
                                 {630.f, 381.f, 40.f, 40.f},   // from the top
                                 {630.f, 499.f, 40.f, 40.f},   // from below
                                 {645.f, 450.f, 10.f, 10.f},   // inside it
                                 {600.f, 400.f, 100.f, 200.f}, // around it
                                 {645.f, 430.f, 0.f, 0.f}};    // a point inside
    for (const hitbox::Box& side : sides)
    {
        const hitbox::GameObject thing = objectAt(side, "thing");
        EXPECT_TRUE(inGateway(gateway, side)) << "it shares area with the gateway; explain says:\n"
                                              << hitbox::toText(hitbox::explain(thing, door));
    }
}

TEST(Task2TouchingIsNotInTheGateway, ApartOnOneAxisIsNotIn)
{
    const hitbox::Box gateway{640.f, 420.f, 20.f, 80.f};
    EXPECT_FALSE(inGateway(gateway, {700.f, 440.f, 40.f, 40.f})) << "right of it, apart";
    EXPECT_FALSE(inGateway(gateway, {560.f, 440.f, 40.f, 40.f})) << "left of it, apart";
    EXPECT_FALSE(inGateway(gateway, {645.f, 300.f, 10.f, 40.f})) << "above it, apart";
    EXPECT_FALSE(inGateway(gateway, {645.f, 600.f, 10.f, 40.f})) << "below it, apart";
    EXPECT_FALSE(inGateway(gateway, {700.f, 100.f, 40.f, 40.f})) << "apart on both axes";
}

TEST(Task2TouchingIsNotInTheGateway, TheGatekeeperOnTheGatePostLeavesTheGatewayClear)
{
    // The level asks inGateway about the gatekeeper and every crate; at the start there is
    // only the gatekeeper, touching the gateway's top.
    const DepotLevel level;
    ASSERT_THAT(level.getGuard(), Touches(level.getGateway()));
    EXPECT_TRUE(level.isGatewayClear())
        << "the gatekeeper only touches the gateway, so the gate may close; explain says:\n"
        << hitbox::toText(hitbox::explain(level.getGuard(), level.getGateway()));
}

namespace
{
// A crate that, when destroyed, notes whether it was still in `world` (its destructor runs
// before GameObject's, which is where the World's safety net takes it out).
class CrateThatWatchesItsEnd : public Crate
{
public:
    CrateThatWatchesItsEnd(sf::Vector2f topLeft, const hitbox::World& world, int& destroyedInWorld)
        : Crate(topLeft), world(world), destroyedInWorld(destroyedInWorld)
    {
    }
    ~CrateThatWatchesItsEnd() override
    {
        if (world.contains(*this))
            ++destroyedInWorld;
    }
    CrateThatWatchesItsEnd(const CrateThatWatchesItsEnd&) = delete;
    CrateThatWatchesItsEnd& operator=(const CrateThatWatchesItsEnd&) = delete;

private:
    const hitbox::World& world;
    int& destroyedInWorld;
};

// Crates in a row, each in `world`; those marked 'D' in `pattern` are delivered (a drop zone
// under them, one collision check).
struct DeliveryScene
{
    explicit DeliveryScene(const std::string& pattern)
    {
        world.add(zone, layer::zone, layer::crate, hitbox::World::Shape::Box, Body::Trigger);
        for (std::size_t index = 0; index < pattern.size(); ++index)
        {
            const float y = pattern[index] == 'D' ? 0.f : 500.f; // in the zone, or far below
            crates.push_back(std::make_unique<CrateThatWatchesItsEnd>(
                sf::Vector2f{50.f * static_cast<float>(index), y}, world, destroyedInWorld));
            crates.back()->setName(std::string(1, pattern[index]) + std::to_string(index));
            world.add(*crates.back(), layer::crate, layer::zone);
        }
        world.checkCollisions();
    }
    std::string names() const
    {
        std::string text;
        for (const std::unique_ptr<Crate>& crate : crates)
            text += (text.empty() ? "" : " ") + crate->getName();
        return text;
    }

    hitbox::World world;
    Piece zone{Kind::DropZone, {0.f, 0.f}, {1000.f, 100.f}};
    int destroyedInWorld = 0;
    std::vector<std::unique_ptr<Crate>> crates;
};
} // namespace

TEST(Task3RemoveEveryDeliveredCrate, TwoCratesDeliveredSideBySideBothGo)
{
    DeliveryScene scene("DD");
    ASSERT_TRUE(scene.crates[0]->isDelivered() && scene.crates[1]->isDelivered());
    EXPECT_EQ(removeDelivered(scene.world, scene.crates), 2);
    EXPECT_EQ(scene.names(), "") << "every delivered crate is destroyed in the same call";
    EXPECT_EQ(scene.world.size(), 1u) << "only the drop zone is left in the World";
}

TEST(Task3RemoveEveryDeliveredCrate, TheOthersStayInTheirOrder)
{
    DeliveryScene scene("DDKDKKDDD");
    EXPECT_EQ(removeDelivered(scene.world, scene.crates), 6);
    EXPECT_EQ(scene.names(), "K2 K4 K5");
    EXPECT_EQ(scene.world.size(), 4u) << "the drop zone and the three crates kept";
    for (const std::unique_ptr<Crate>& crate : scene.crates)
        EXPECT_TRUE(scene.world.contains(*crate)) << crate->getName() << " is still in the World";
    EXPECT_EQ(removeDelivered(scene.world, scene.crates), 0) << "nothing more to remove";
}

TEST(Task3RemoveEveryDeliveredCrate, NoneDeliveredRemovesNone)
{
    DeliveryScene scene("KKK");
    EXPECT_EQ(removeDelivered(scene.world, scene.crates), 0);
    EXPECT_EQ(scene.names(), "K0 K1 K2");
    std::vector<std::unique_ptr<Crate>> none;
    EXPECT_EQ(removeDelivered(scene.world, none), 0) << "an empty list";
}

TEST(Task3RemoveEveryDeliveredCrate, ACrateLeavesTheWorldBeforeItIsDestroyed)
{
    // The World keeps pointers to crates it does not own: out of it first, then destroyed.
    // (Hitbox's World would take a destroyed crate out by itself, so only the crate can tell.)
    DeliveryScene scene("KDK");
    EXPECT_EQ(removeDelivered(scene.world, scene.crates), 1);
    EXPECT_EQ(scene.destroyedInWorld, 0)
        << "a delivered crate was destroyed while still in the World: world.remove first";
    EXPECT_EQ(scene.names(), "K0 K2");
}

// The program's own run (lab16_find_the_bug, no keys), checked at every step: no crate that
// was delivered in a step is still on the belts after it. Two crates reach the drop zone in
// the same step only now and then: a failure prints the command that opens the run there.
TEST(Task3RemoveEveryDeliveredCrate, InTheProgramsRunNoDeliveredCrateOutlivesItsStep)
{
    DepotLevel level;
    scenereplay::RecordedScene scene(level, {programTitle, 1});
    hitbox::Input input;
    for (int i = 0; i < 120 * 20; ++i)
    {
        scene.step(input);
        for (int crate = 0; crate < level.getCrateCount(); ++crate)
            ASSERT_FALSE(level.getCrate(crate).isDelivered())
                << "step " << scene.stepCount() << ": " << level.getCrate(crate).getName()
                << " was delivered and is still on the belt" << scene.replayCommand();
    }
}
