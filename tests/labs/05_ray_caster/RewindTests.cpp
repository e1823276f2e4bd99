// Rewinding lab 5 (RayLevel::saveState, support/RewindCheck.h): the window restores a copy of
// the whole level and re-simulates the input (the arrows move the player, the mouse aims the
// ray) from there. A shown step is the step as it was, bit for bit. (Not a task's test: the
// starter passes it too.)
#include "support/RewindCheck.h"

#include "RayLevel.h"

#include "hitbox/app/Csv.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

// Every value a step of RayLevel changes, exactly.
std::string rayState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const RayLevel&>(shown);
    std::string text = level.describeState() + '\n';
    for (float value : {level.getPlayer().getPosition().x, level.getPlayer().getPosition().y})
        text += hitbox::exactText(value) + ' ';
    for (const hitbox::Hit& hit : level.getLastHits())
        text += hitbox::exactText(hit.time) + ' ';
    return text;
}

// The mouse sweeps the ray around; the player walks right, then up.
void keys(hitbox::Input& input, long long step)
{
    input.setMousePosition({300.f + 2.f * static_cast<float>(step), 200.f});
    if (step == 60)
        input.setKeyDown(sf::Keyboard::Key::Right);
    if (step == 130)
    {
        input.setKeyUp(sf::Keyboard::Key::Right);
        input.setKeyDown(sf::Keyboard::Key::Up);
    }
}

} // namespace

TEST(Rewind, EveryKeptStepOfTheRayCasterIsShownAsItWas)
{
    const rewindcheck::Program program{[] { return std::make_unique<RayLevel>(); }, rayState, keys};
    const rewindcheck::Seen seen = rewindcheck::checkRewind(program, 220, {200}, 120);
    EXPECT_FALSE(seen.rebuilt) << "lab 5 saves its state: the rewind restores it";
    EXPECT_GT(seen.stepsShown, 0);
}
