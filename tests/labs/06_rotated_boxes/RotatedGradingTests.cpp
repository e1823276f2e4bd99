// Grading tests for lab 6 (rotated boxes). Each suite checks one task of README.md, and runs
// only that task's code: task 2's tests cast the shadows themselves, tasks 3 and 4 let the
// level test box pairs with the framework's SAT. So one mistake costs one task.
#include "labs/06_rotated_boxes/RotatedChecks.h"

#include "RotatedLevel.h"
#include "Sat.h"

#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/geometry/Polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

using namespace rotatedchecks;

RotatedLevel labLevelWithFrameworkSat()
{
    RotatedLevel level;
    level.setFrameworkSat(true);
    level.update(hitbox::stepSeconds);
    return level;
}

} // namespace

TEST(Task1Shadow, AnAxisAlignedBoxCastsItsWidthAndHeight)
{
    const hitbox::Polygon square = box({100.f, 50.f}, {20.f, 10.f}, 0.f);
    const Shadow onX = projectOnto(square, {1.f, 0.f});
    EXPECT_NEAR(onX.min, 80.f, 1e-3f);
    EXPECT_NEAR(onX.max, 120.f, 1e-3f);
    const Shadow onY = projectOnto(square, {0.f, 1.f});
    EXPECT_NEAR(onY.min, 40.f, 1e-3f);
    EXPECT_NEAR(onY.max, 60.f, 1e-3f);
    const Shadow backwards = projectOnto(square, {-1.f, 0.f});
    EXPECT_NEAR(backwards.min, -120.f, 1e-3f);
    EXPECT_NEAR(backwards.max, -80.f, 1e-3f);
}

TEST(Task1Shadow, ATurnedSquareCastsItsDiagonal)
{
    const hitbox::Polygon diamond = box({0.f, 0.f}, {10.f, 10.f}, 45.f);
    const Shadow onX = projectOnto(diamond, {1.f, 0.f});
    EXPECT_NEAR(onX.min, -10.f * std::sqrt(2.f), 1e-3f);
    EXPECT_NEAR(onX.max, 10.f * std::sqrt(2.f), 1e-3f);
}

TEST(Task1Shadow, EveryCornerCountsTheFirstOneToo)
{
    // Triangles whose first corner alone is the nearest (then the furthest) along x, all of
    // them well away from zero: the shadow runs from the smallest to the largest corner.
    const hitbox::Polygon nearFirst{{{110.f, 0.f}, {120.f, 5.f}, {130.f, -5.f}}};
    const Shadow a = projectOnto(nearFirst, {1.f, 0.f});
    EXPECT_NEAR(a.min, 110.f, 1e-4f);
    EXPECT_NEAR(a.max, 130.f, 1e-4f);
    const hitbox::Polygon farFirst{{{130.f, 0.f}, {110.f, 5.f}, {120.f, -5.f}}};
    const Shadow b = projectOnto(farFirst, {1.f, 0.f});
    EXPECT_NEAR(b.min, 110.f, 1e-4f);
    EXPECT_NEAR(b.max, 130.f, 1e-4f);
}

TEST(Task2SeparatingAxis, BoxesWithAGapAreSeparatedAndTheGapIsMeasured)
{
    const SatResult result =
        sat(box({0.f, 0.f}, {10.f, 10.f}, 0.f), box({35.f, 0.f}, {10.f, 10.f}, 0.f));
    EXPECT_TRUE(result.separated);
    EXPECT_NEAR(result.gap, 15.f, 1e-3f);
    EXPECT_NEAR(std::abs(result.axis.x), 1.f, 1e-5f);
}

TEST(Task2SeparatingAxis, TurnedBoxesWhoseBoundingBoxesOverlapCanStillBeApart)
{
    // The held box and the diamond of the lab's start: the AABB test would say "hit".
    const SatResult result =
        sat(box({560.f, 330.f}, {90.f, 40.f}, 25.f), box({420.f, 470.f}, {60.f, 60.f}, 45.f));
    EXPECT_TRUE(result.separated);
    EXPECT_GT(result.gap, 0.f);
}

TEST(Task2SeparatingAxis, OverlappingBoxesGiveTheMinimumTranslationVector)
{
    // A overlaps B by 5 px from the right: the shortest way out is 5 px to the right.
    const SatResult result =
        sat(box({15.f, 0.f}, {10.f, 10.f}, 0.f), box({0.f, 2.f}, {10.f, 10.f}, 0.f));
    EXPECT_FALSE(result.separated);
    EXPECT_NEAR(result.depth(), 5.f, 1e-3f);
    EXPECT_NEAR(result.axis.x, 1.f, 1e-5f);
    EXPECT_NEAR(result.axis.y, 0.f, 1e-5f);
}

TEST(Task2SeparatingAxis, TouchingIsNotOverlapping)
{
    const SatResult result =
        sat(box({0.f, 0.f}, {10.f, 10.f}, 0.f), box({20.f, 0.f}, {10.f, 10.f}, 0.f));
    EXPECT_TRUE(result.separated);
    EXPECT_NEAR(result.gap, 0.f, 1e-4f);
}

TEST(Task2SeparatingAxis, AgreesWithTheFrameworkOnThousandsOfRandomBoxes)
{
    std::mt19937 random(6);
    std::uniform_real_distribution<float> position(0.f, 200.f);
    std::uniform_real_distribution<float> half(5.f, 60.f);
    std::uniform_real_distribution<float> angle(-180.f, 180.f);
    int overlaps = 0;
    for (int i = 0; i < 5000; ++i)
    {
        const hitbox::Polygon a =
            box({position(random), position(random)}, {half(random), half(random)}, angle(random));
        const hitbox::Polygon b =
            box({position(random), position(random)}, {half(random), half(random)}, angle(random));
        const SatResult mine = sat(a, b);
        const hitbox::Contact reference = hitbox::polygonVsPolygon(a, b);
        // Near-touching pairs can go either way by a rounding error: skip them.
        if (std::abs(reference.depth) < 1e-3f && std::abs(mine.gap) < 1e-3f)
            continue;
        ASSERT_EQ(!mine.separated, reference.hit) << "case " << i;
        if (reference.hit)
        {
            ++overlaps;
            // Tolerance: float corners of boxes up to 260 px from the origin.
            EXPECT_NEAR(mine.depth(), reference.depth, 1e-2f) << "case " << i;
        }
    }
    EXPECT_GT(overlaps, 500);
}

TEST(Task2SeparatingAxis, TheLabsHeldBoxOverlapsItsNeighbourNotTheDiamond)
{
    const RotatedLevel level; // the held box starts over its neighbour, the diamond apart
    const std::vector<Shape>& shapes = level.getShapes();
    EXPECT_FALSE(sat(shapes[0].polygon(), shapes[1].polygon()).separated);
    EXPECT_TRUE(sat(shapes[0].polygon(), shapes[2].polygon()).separated);
}

TEST(Task3WheelTurns, EachNotchTurnsTheHeldShape)
{
    RotatedLevel level = labLevelWithFrameworkSat();
    const float before = level.getShapes()[0].body.angleDegrees;
    hitbox::Input input;
    input.addMouseWheel(2.f);
    stepWith(level, input);
    EXPECT_NEAR(level.getShapes()[0].body.angleDegrees,
                before + 2.f * RotatedLevel::degreesPerNotch, 1e-3f);
    input.addMouseWheel(-1.f);
    stepWith(level, input);
    EXPECT_NEAR(level.getShapes()[0].body.angleDegrees, before + RotatedLevel::degreesPerNotch,
                1e-3f);
    stepWith(level, input); // no wheel: no turn
    EXPECT_NEAR(level.getShapes()[0].body.angleDegrees, before + RotatedLevel::degreesPerNotch,
                1e-3f);
}

TEST(Task3WheelTurns, TurningCanMakeShapesOverlap)
{
    // A long thin box across a square's corner region: turned 90 degrees it clears it.
    RotatedLevel level = levelWithFrameworkSat({{{{100.f, 100.f}, {60.f, 5.f}, 0.f}, false},
                                                {{{100.f, 130.f}, {20.f, 20.f}, 0.f}, false}});
    ASSERT_FALSE(level.isOverlapping(0));
    hitbox::Input input;
    input.addMouseWheel(6.f); // 90 degrees: the box now reaches down into the square
    stepWith(level, input);
    EXPECT_TRUE(level.isOverlapping(0));
}

TEST(Task4PushOut, SpaceMovesTheHeldShapeOutAlongTheMtv)
{
    RotatedLevel level = labLevelWithFrameworkSat();
    const hitbox::Vec2 before = level.getShapes()[0].body.center;
    const PairView* nearest = level.getNearestPair();
    ASSERT_NE(nearest, nullptr);
    ASSERT_TRUE(nearest->overlapping);
    const hitbox::Vec2 expectedMove = nearest->axis * -nearest->gap;

    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Space);
    stepWith(level, input);
    const hitbox::Vec2 moved = level.getShapes()[0].body.center - before;
    EXPECT_NEAR(moved.x, expectedMove.x, 1e-2f);
    EXPECT_NEAR(moved.y, expectedMove.y, 1e-2f);
    expectPushedOut(level);
}

TEST(Task4PushOut, OutOfTheCapsuleToo)
{
    RotatedLevel level = levelWithFrameworkSat({{{{200.f, 200.f}, {40.f, 40.f}, 30.f}, false},
                                                {{{250.f, 250.f}, {60.f, 25.f}, -20.f}, true}});
    ASSERT_TRUE(level.isOverlapping(0));
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Space);
    stepWith(level, input);
    EXPECT_FALSE(level.isOverlapping(0));
}

TEST(Task4PushOut, ADraggedShapeIsPushedOutOfWhatItWasDroppedOn)
{
    RotatedLevel level = levelWithFrameworkSat({{{{100.f, 100.f}, {30.f, 30.f}, 0.f}, false},
                                                {{{400.f, 100.f}, {30.f, 30.f}, 20.f}, false}});
    hitbox::Input input;
    // Grab shape 1 at its centre, drag it onto shape 0, then press Space.
    input.setMousePosition({400.f, 100.f});
    input.setMouseLDown(true);
    stepWith(level, input);
    EXPECT_EQ(level.getHeld(), 1u);
    input.setMousePosition({130.f, 110.f});
    stepWith(level, input);
    input.setMouseLDown(false);
    stepWith(level, input);
    ASSERT_TRUE(level.isOverlapping(1));
    input.setKeyDown(sf::Keyboard::Key::Space);
    stepWith(level, input);
    expectPushedOut(level);
}

TEST(Task4PushOut, EachPushIntoAnotherShapeGoesRoundAgain)
{
    // A staircase: out of shape 4 (left), into shape 3 (up), into shape 2 (left), into
    // shape 1 (up). Each push lands in a shape the round has already passed, so it takes
    // four rounds, and after the last the held shape touches but overlaps nothing.
    RotatedLevel level = levelWithFrameworkSat(
        {axisAligned(-10.f, -10.f, 10.f, 10.f), axisAligned(-100.f, 9.77f, -11.05f, 100.f),
         axisAligned(8.9f, -100.f, 100.f, -10.05f), axisAligned(-100.f, 9.8f, -10.5f, 100.f),
         axisAligned(9.f, -100.f, 100.f, 100.f)});
    ASSERT_TRUE(level.isOverlapping(0));
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Space);
    stepWith(level, input);
    expectPushedOut(level);
    const hitbox::Vec2 center = level.getShapes()[0].body.center;
    EXPECT_NEAR(center.x, -1.1f, 1e-3f);
    EXPECT_NEAR(center.y, -0.23f, 1e-3f);
}
