// Rewinding lab 6 (RotatedLevel::saveState, support/RewindCheck.h): the window restores a copy
// of the whole level and re-simulates the input (the mouse drags and turns a shape) from
// there. A shown step is the step as it was, bit for bit. (Not a task's test: the starter
// passes it too.)
#include "support/RewindCheck.h"

#include "RotatedLevel.h"

#include "hitbox/app/Csv.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace
{

// Every value a step of RotatedLevel changes, exactly.
std::string rotatedState(const hitbox::Level& shown)
{
    const auto& level = dynamic_cast<const RotatedLevel&>(shown);
    std::string text = level.describeState() + '\n' + std::to_string(level.getHeld()) + '\n';
    for (const Shape& shape : level.getShapes())
        for (float value : {shape.body.center.x, shape.body.center.y, shape.body.angleDegrees})
            text += hitbox::exactText(value) + ' ';
    for (const PairView& pair : level.getPairs())
        text += '\n' + std::to_string(pair.other) + (pair.overlapping ? " overlapping " : " ") +
                hitbox::exactText(pair.gap);
    return text;
}

// The held shape spins; the mouse grabs it and drags it across the others, turning it.
std::unique_ptr<hitbox::Level> spinning()
{
    auto level = std::make_unique<RotatedLevel>();
    level->setSpin(90.f);
    return level;
}

void mouse(hitbox::Input& input, long long step)
{
    const sf::Vector2f grab = hitbox::toSfml(RotatedLevel().getShapes()[0].body.center);
    if (step == 20)
    {
        input.setMousePosition(grab);
        input.setMouseLDown(true);
    }
    if (step > 20 && step < 200)
        input.setMousePosition(grab + sf::Vector2f(3.f * static_cast<float>(step - 20), 0.f));
    if (step == 120)
        input.addMouseWheel(1.f);
    if (step == 200)
        input.setMouseLDown(false);
}

} // namespace

TEST(Rewind, EveryKeptStepOfTheShapesIsShownAsItWas)
{
    const rewindcheck::Seen seen =
        rewindcheck::checkRewind({spinning, rotatedState, mouse}, 220, {180}, 120);
    EXPECT_FALSE(seen.rebuilt) << "lab 6 saves its state: the rewind restores it";
    EXPECT_GT(seen.stepsShown, 0);
}
