// Rewinding lab 7 (PoolLevel::saveState, support/RewindCheck.h): the window restores a copy
// of the whole level and re-simulates the input (the mouse aims, Space shoots) from there. A
// shown step is the step as it was, bit for bit. (Not a task's test: the starter passes it
// too.)
#include "support/RewindCheck.h"

#include "PoolLevel.h"

#include "hitbox/app/Csv.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

// Every value a step of PoolLevel changes, exactly.
std::string poolState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const PoolLevel&>(shown);
    std::string text = level.describeState() + '\n';
    for (const Ball& ball : level.getBalls())
        for (float value :
             {ball.shape.center.x, ball.shape.center.y, ball.velocity.x, ball.velocity.y})
            text += hitbox::exactText(value) + ' ';
    return text;
}

// Aim at the rack and shoot (Space) twice, the second time harder (Up).
void keys(hitbox::Input& input, long long step)
{
    input.setMousePosition({800.f, 330.f + static_cast<float>(step % 40)});
    if (step == 10 || step == 120)
        input.setKeyDown(sf::Keyboard::Key::Space);
    if (step == 11 || step == 121)
        input.setKeyUp(sf::Keyboard::Key::Space);
    if (step == 100)
        input.setKeyDown(sf::Keyboard::Key::Up);
    if (step == 101)
        input.setKeyUp(sf::Keyboard::Key::Up);
}

} // namespace

TEST(Rewind, EveryKeptStepOfThePoolTableIsShownAsItWas)
{
    const rewindcheck::Program program{[] { return std::make_unique<PoolLevel>(); }, poolState,
                                       keys};
    const rewindcheck::Seen seen = rewindcheck::checkRewind(program, 220, {200}, 120);
    EXPECT_FALSE(seen.rebuilt) << "lab 7 saves its state: the rewind restores it";
    EXPECT_GT(seen.stepsShown, 0);
}
