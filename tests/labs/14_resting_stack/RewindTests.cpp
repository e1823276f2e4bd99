// Rewinding lab 14 (StackLevel::saveState, support/RewindCheck.h): the window restores a copy
// of the whole level and re-simulates the input from there (Up, Down and R here).
// A shown step is the step as it was, bit for bit.
// (Not a task's test: the starter passes it too.)
#include "support/RewindCheck.h"

#include "StackLevel.h"

#include "hitbox/app/Csv.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

// Every value a step of StackLevel changes, exactly (the readout is in describeState).
std::string stackState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const StackLevel&>(shown);
    std::string text = level.describeState() + '\n';
    for (int stack = 0; stack < 2; ++stack)
    {
        text += std::to_string(level.getPasses(stack)) + ' ' +
                hitbox::exactText(level.getShake(stack)) + '\n';
        for (const Crate& crate : level.getCrates(stack))
            text += hitbox::exactText(crate.left) + ' ' + hitbox::exactText(crate.top) + ' ' +
                    hitbox::exactText(crate.velocityY) + '\n';
    }
    return text;
}

// Down (fewer passes: the right stack shakes) a few times, then R restacks both.
void keys(hitbox::Input& input, long long step)
{
    if (step >= 80 && step < 92)
    {
        if (step % 2 == 0)
            input.setKeyDown(sf::Keyboard::Key::Down);
        else
            input.setKeyUp(sf::Keyboard::Key::Down);
    }
    if (step == 150)
        input.setKeyDown(sf::Keyboard::Key::R);
    if (step == 151)
        input.setKeyUp(sf::Keyboard::Key::R);
}

} // namespace

TEST(Rewind, EveryKeptStepOfTheStacksIsShownAsItWas)
{
    const rewindcheck::Program program{[] { return std::make_unique<StackLevel>(); }, stackState,
                                       keys};
    const rewindcheck::Seen seen = rewindcheck::checkRewind(program, 180, {160}, 90);
    EXPECT_FALSE(seen.rebuilt) << "lab 14 saves its state: the rewind restores it";
    EXPECT_GT(seen.stepsShown, 0);
}
