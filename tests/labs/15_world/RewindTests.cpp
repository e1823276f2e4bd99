// Rewinding lab 15 (hitbox::RewindLevel, support/RewindCheck.h): the level keeps its objects in
// a hitbox::World, whose per-pair contacts decide Enter and Exit, and has no saveState; the
// window rewinds it by building it again and re-simulating the input. A shown step is the step
// as it was, contacts and all: no second Enter for a pair already touching, no missing Exit.
// (Not a task's test: the starter passes it too.)
#include "support/RewindCheck.h"

#include "Pieces.h"
#include "WorldLevel.h"

#include "hitbox/app/Csv.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

void addObject(std::string& text, const hitbox::GameObject& object)
{
    for (float value : {object.getPosition().x, object.getPosition().y, object.getVelocity().x,
                        object.getVelocity().y})
        text += hitbox::exactText(value) + ' ';
    text += object.isAlive() ? "alive\n" : "dead\n";
}

// Every value a step of WorldLevel changes, exactly.
std::string worldState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const WorldLevel&>(shown);
    std::string text = level.describeState() + '\n';
    addObject(text, level.getPlayer());
    text += hitbox::exactText(level.getPlayer().getBlinkLeft()) + '\n';
    for (int i = 0; i < level.getCoinCount(); ++i)
        addObject(text, level.getCoin(i));
    for (int i = 0; i < level.getEnemyCount(); ++i)
    {
        addObject(text, level.getEnemy(i));
        text += std::to_string(level.getEnemy(i).getBumpCount()) + '\n';
    }
    return text;
}

// Two enemies that start overlapping and bump apart slowly (Enter, many Stays, Exit across the
// oldest kept step), and the player walked by the Right arrow onto a coin (Enter, and the Exit
// when the collected coin leaves the World).
std::unique_ptr<hitbox::Level> scene()
{
    auto level = std::make_unique<WorldLevel>(3);
    level->removeAllButThePlayer();
    level->placePlayer({600.f, 340.f});
    level->addEnemy({300.f, 300.f}, {20.f, 0.f});
    level->addEnemy({306.f, 300.f}, {-20.f, 0.f});
    level->addCoin({700.f, 340.f});
    return level;
}

void keys(hitbox::Input& input, long long step)
{
    if (step == 5)
        input.setKeyDown(sf::Keyboard::Key::Right);
    if (step == 60)
        input.setKeyUp(sf::Keyboard::Key::Right);
}

} // namespace

TEST(Rewind, EveryKeptStepOfTheWorldIsShownAsItWasContactsAndAll)
{
    const rewindcheck::Seen seen =
        rewindcheck::checkRewind({scene, worldState, keys}, 150, {130}, 100);
    EXPECT_TRUE(seen.rebuilt) << "lab 15 has no saveState: the rewind rebuilds it";
    // The kept steps had pairs that began, went on and ended: there was something to lose.
    EXPECT_GT(seen.enters, 0);
    EXPECT_GT(seen.stays, 0);
    EXPECT_GT(seen.exits, 0);
}
