// Rewinding lab 16 (hitbox::RewindLevel, support/RewindCheck.h): the depot keeps its crates,
// plate and gate in a hitbox::World and has no saveState; the window rewinds it by building it
// again and re-simulating the input. A shown step is the step as it was: the crate that stands
// on the plate across the oldest kept step goes on with Stay and leaves with one Exit (step
// 640), and the plate counts it once. (Not a task's test: the exercise passes it too.)
#include "support/RewindCheck.h"

#include "DepotLevel.h"
#include "Pieces.h"

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
    text += '\n';
}

// Every value a step of DepotLevel changes, exactly.
std::string depotState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const DepotLevel&>(shown);
    std::string text = level.describeState() + '\n';
    text += level.getPlate().isPressed() ? "pressed " : "up ";
    text += level.isGateOpen() ? "open " : "closed ";
    text += std::to_string(level.getDelivered()) + '\n';
    addObject(text, level.getGuard());
    for (int i = 0; i < level.getCrateCount(); ++i)
    {
        addObject(text, level.getCrate(i));
        text += level.getCrate(i).isDelivered() ? "delivered\n" : "on the belt\n";
    }
    return text;
}

// The gatekeeper steps down into the gateway and back up onto the gate post while the kept
// steps run (an Enter and an Exit of its own).
void keys(hitbox::Input& input, long long step)
{
    if (step == 630)
        input.setKeyDown(sf::Keyboard::Key::Down);
    if (step == 640)
    {
        input.setKeyUp(sf::Keyboard::Key::Down);
        input.setKeyDown(sf::Keyboard::Key::Up);
    }
    if (step == 650)
        input.setKeyUp(sf::Keyboard::Key::Up);
}

} // namespace

TEST(Rewind, EveryKeptStepOfTheDepotIsShownAsItWasContactsAndAll)
{
    const rewindcheck::Program program{[] { return std::make_unique<DepotLevel>(); }, depotState,
                                       keys};
    // Kept: steps 625 to 670. Crate 1 is on the plate from step 441 to 640, crate 2 in the
    // gateway from 601 to 660: both began before the oldest kept step.
    const rewindcheck::Seen seen = rewindcheck::checkRewind(program, 700, {670}, 45);
    EXPECT_TRUE(seen.rebuilt) << "lab 16 has no saveState: the rewind rebuilds it";
    EXPECT_GT(seen.enters, 0);
    EXPECT_GT(seen.stays, 0);
    EXPECT_GT(seen.exits, 0);
}
