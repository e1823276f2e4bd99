// Rewinding lab 12 (CrowdLevel::saveState, support/RewindCheck.h): the window restores a copy
// of the whole level and re-simulates the input (M switches the method) from there. A shown
// step is the step as it was, bit for bit. (Not a task's test: the starter passes it too.)
#include "support/RewindCheck.h"

#include "CrowdLevel.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

// What a step of CrowdLevel changes, as its getters show it: the pairs found, in order.
std::string crowdState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const CrowdLevel&>(shown);
    std::string text = level.describeState() + '\n';
    text += std::to_string(level.getLastExactTests()) + " exact tests:";
    for (const Pair& pair : level.getLastPairs())
        text += ' ' + std::to_string(pair.first) + '-' + std::to_string(pair.second);
    return text;
}

// M (the next method: the grid) while the kept steps run.
void keys(hitbox::Input& input, long long step)
{
    if (step == 130)
        input.setKeyDown(sf::Keyboard::Key::M);
    if (step == 131)
        input.setKeyUp(sf::Keyboard::Key::M);
}

} // namespace

TEST(Rewind, EveryKeptStepOfTheCrowdIsShownAsItWas)
{
    const rewindcheck::Program program{[] { return std::make_unique<CrowdLevel>(120, 4); },
                                       crowdState, keys};
    const rewindcheck::Seen seen = rewindcheck::checkRewind(program, 220, {200}, 120);
    EXPECT_FALSE(seen.rebuilt) << "lab 12 saves its state: the rewind restores it";
    EXPECT_GT(seen.stepsShown, 0);
}
