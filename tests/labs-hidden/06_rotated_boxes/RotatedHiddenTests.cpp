// Hidden variants of lab 6's grading tests: the same behaviour as RotatedGradingTests.cpp with
// other boxes, angles, axes and directions. The instructor's build and the class grader run
// them; the student handout leaves tests/labs-hidden/ out, so no one can tune an answer to
// them. As in the visible tests, each task's tests run that task's code alone: task 2's cast
// the shadows themselves, tasks 3 and 4 let the level test box pairs with the framework's SAT.
#include "labs/06_rotated_boxes/RotatedChecks.h"

#include "RotatedLevel.h"
#include "Sat.h"

#include "hitbox/app/Input.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Vec2.h"

#include <SFML/Window/Keyboard.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{

using namespace rotatedchecks;

// The unit vector `degrees` clockwise on screen from the x axis (toPolygon's turn).
hitbox::Vec2 direction(float degrees)
{
    const float radians = degrees * hitbox::pi / 180.f;
    return {std::cos(radians), std::sin(radians)};
}

void press(RotatedLevel& level, sf::Keyboard::Key key)
{
    hitbox::Input input;
    input.setKeyDown(key);
    stepWith(level, input);
}

// How far the angle `after` is turned from `before`, in (-180, 180]: the level keeps the held
// shape's angle in [0, 360), so a turn below 0 shows up as a large angle.
float turnBetween(float before, float after)
{
    return std::remainder(after - before, 360.f);
}

} // namespace

TEST(Task1Shadow, HiddenATurnedBoxCastsOnItsOwnAndOnPlainAxes)
{
    // A 50 x 20 box turned 30 degrees, left of and below the origin: its shadows on its own
    // axes are its width and height, on the plain axes a mix of both, and on the negative y
    // axis every value is below zero.
    const hitbox::Vec2 center{-60.f, 30.f};
    const hitbox::Polygon turned = box(center, {25.f, 10.f}, 30.f);
    const hitbox::Vec2 along = direction(30.f);
    const hitbox::Vec2 across = direction(120.f);
    const float c = std::cos(30.f * hitbox::pi / 180.f);

    const Shadow onAlong = projectOnto(turned, along);
    EXPECT_NEAR(onAlong.min, hitbox::dot(center, along) - 25.f, 1e-3f);
    EXPECT_NEAR(onAlong.max, hitbox::dot(center, along) + 25.f, 1e-3f);
    const Shadow onAcross = projectOnto(turned, across);
    EXPECT_NEAR(onAcross.min, hitbox::dot(center, across) - 10.f, 1e-3f);
    EXPECT_NEAR(onAcross.max, hitbox::dot(center, across) + 10.f, 1e-3f);
    const Shadow onX = projectOnto(turned, {1.f, 0.f});
    EXPECT_NEAR(onX.min, -60.f - (25.f * c + 10.f * 0.5f), 1e-3f);
    EXPECT_NEAR(onX.max, -60.f + (25.f * c + 10.f * 0.5f), 1e-3f);
    const Shadow upwards = projectOnto(turned, {0.f, -1.f});
    EXPECT_NEAR(upwards.min, -30.f - (25.f * 0.5f + 10.f * c), 1e-3f);
    EXPECT_NEAR(upwards.max, -30.f + (25.f * 0.5f + 10.f * c), 1e-3f);
}

TEST(Task1Shadow, HiddenEveryCornerCountsOnASlantedAxis)
{
    // Quadrilaterals on the axis (0.6, -0.8): one wholly below zero with its lowest corner
    // last, one wholly above zero with its highest corner first. A shadow started at 0, or
    // one that skips the first or the last corner, gets one end wrong.
    const hitbox::Vec2 axis{0.6f, -0.8f};
    const hitbox::Polygon below{{{-70.f, 40.f}, {-50.f, 10.f}, {-20.f, 30.f}, {-40.f, 70.f}}};
    const Shadow a = projectOnto(below, axis);
    EXPECT_NEAR(a.min, -80.f, 1e-3f);
    EXPECT_NEAR(a.max, -36.f, 1e-3f);
    const hitbox::Polygon above{{{100.f, -70.f}, {80.f, -30.f}, {50.f, -60.f}, {70.f, -90.f}}};
    const Shadow b = projectOnto(above, axis);
    EXPECT_NEAR(b.min, 72.f, 1e-3f);
    EXPECT_NEAR(b.max, 116.f, 1e-3f);
}

TEST(Task2SeparatingAxis, HiddenOverlapsPushOutLeftwardsOrDownwards)
{
    // A 3 px into B from the left (and 15 px down into it): the way out is 3 px to the left.
    const SatResult left =
        sat(box({-12.f, 5.f}, {10.f, 10.f}, 0.f), box({5.f, 0.f}, {10.f, 10.f}, 0.f));
    EXPECT_FALSE(left.separated);
    EXPECT_NEAR(left.depth(), 3.f, 1e-3f);
    EXPECT_NEAR(left.gap, -3.f, 1e-3f);
    EXPECT_NEAR(left.axis.x, -1.f, 1e-5f);
    EXPECT_NEAR(left.axis.y, 0.f, 1e-5f);
    // A 2 px into B from below, and deep into it sideways: 2 px down is the way out.
    const SatResult down =
        sat(box({3.f, 26.f}, {10.f, 10.f}, 0.f), box({0.f, 10.f}, {12.f, 8.f}, 0.f));
    EXPECT_FALSE(down.separated);
    EXPECT_NEAR(down.depth(), 2.f, 1e-3f);
    EXPECT_NEAR(down.axis.x, 0.f, 1e-5f);
    EXPECT_NEAR(down.axis.y, 1.f, 1e-5f);
}

TEST(Task2SeparatingAxis, HiddenTurnedBoxesGetOutAlongTheirTurnedSide)
{
    // Both turned 30 degrees, B 30 px further along their long side: 5 px of overlap that
    // way, more than 20 px across, so the way out is backwards along the turned side.
    const hitbox::Vec2 along = direction(30.f);
    const SatResult result =
        sat(box({0.f, 0.f}, {20.f, 10.f}, 30.f), box(along * 30.f, {15.f, 12.f}, 30.f));
    EXPECT_FALSE(result.separated);
    EXPECT_NEAR(result.depth(), 5.f, 1e-3f);
    EXPECT_NEAR(result.axis.x, -along.x, 1e-4f);
    EXPECT_NEAR(result.axis.y, -along.y, 1e-4f);
}

// Edge rule: touching is not overlapping.
TEST(Task2SeparatingAxis, HiddenTouchingTopToBottomIsApartAQuarterPixelMoreIsNot)
{
    const hitbox::Polygon a = box({7.f, -3.f}, {6.f, 4.f}, 0.f); // y from -7 to 1
    const SatResult touching = sat(a, box({4.f, 9.f}, {5.f, 8.f}, 0.f));
    EXPECT_TRUE(touching.separated);
    EXPECT_NEAR(touching.gap, 0.f, 1e-4f);
    const SatResult inside = sat(a, box({4.f, 8.75f}, {5.f, 8.f}, 0.f));
    EXPECT_FALSE(inside.separated);
    EXPECT_NEAR(inside.depth(), 0.25f, 1e-4f);
    EXPECT_NEAR(inside.axis.y, -1.f, 1e-5f);
}

TEST(Task2SeparatingAxis, HiddenAgreesWithTheFrameworkOnThinBoxesBelowTheOrigin)
{
    // Other boxes than the visible test's: thin ones, at negative coordinates, and the gap of
    // separated pairs compared too (the axis of the largest gap).
    std::mt19937 random(20240917);
    std::uniform_real_distribution<float> position(-300.f, -60.f);
    std::uniform_real_distribution<float> half(2.f, 80.f);
    std::uniform_real_distribution<float> angle(-180.f, 180.f);
    int overlaps = 0;
    int apart = 0;
    for (int i = 0; i < 3000; ++i)
    {
        const hitbox::Polygon a =
            box({position(random), position(random)}, {half(random), half(random)}, angle(random));
        const hitbox::Polygon b =
            box({position(random), position(random)}, {half(random), half(random)}, angle(random));
        const SatResult mine = sat(a, b);
        const hitbox::AxisReport reference = hitbox::findSeparatingAxis(a, b);
        // Near-touching pairs can go either way by a rounding error: skip them.
        if (std::abs(reference.gap) < 1e-3f && std::abs(mine.gap) < 1e-3f)
            continue;
        ASSERT_EQ(mine.separated, reference.separated) << "case " << i;
        // Tolerance: float corners of boxes up to 420 px from the origin.
        EXPECT_NEAR(mine.gap, reference.gap, 1e-2f) << "case " << i;
        ++(mine.separated ? apart : overlaps);
    }
    EXPECT_GT(overlaps, 300);
    EXPECT_GT(apart, 300);
}

TEST(Task3WheelTurns, HiddenTheWheelTurnsTheShapeHeldAfterTab)
{
    // Hold the third shape, then turn 3 notches back and 5 forward: only it turns, by
    // -45 and then +75 degrees.
    RotatedLevel level = levelWithFrameworkSat({{{{100.f, 100.f}, {30.f, 20.f}, 10.f}, false},
                                                {{{300.f, 120.f}, {25.f, 25.f}, 40.f}, false},
                                                {{{200.f, 320.f}, {40.f, 15.f}, 70.f}, false}});
    press(level, sf::Keyboard::Key::Tab);
    press(level, sf::Keyboard::Key::Tab);
    ASSERT_EQ(level.getHeld(), 2u);
    const float before = level.getShapes()[2].body.angleDegrees;
    hitbox::Input input;
    input.addMouseWheel(-3.f);
    stepWith(level, input);
    EXPECT_NEAR(turnBetween(before, level.getShapes()[2].body.angleDegrees),
                -3.f * RotatedLevel::degreesPerNotch, 1e-3f);
    input.addMouseWheel(5.f);
    stepWith(level, input);
    EXPECT_NEAR(turnBetween(before, level.getShapes()[2].body.angleDegrees),
                2.f * RotatedLevel::degreesPerNotch, 1e-3f);
    EXPECT_NEAR(level.getShapes()[0].body.angleDegrees, 10.f, 1e-5f);
    EXPECT_NEAR(level.getShapes()[1].body.angleDegrees, 40.f, 1e-5f);
}

TEST(Task3WheelTurns, HiddenTurningBackCanSeparateShapes)
{
    // A long thin box poking into a square from the left: turned back 90 degrees it stands
    // upright, clear of the square.
    RotatedLevel level = levelWithFrameworkSat({{{{300.f, 200.f}, {50.f, 4.f}, 0.f}, false},
                                                {{{360.f, 200.f}, {15.f, 15.f}, 0.f}, false}});
    ASSERT_TRUE(level.isOverlapping(0));
    hitbox::Input input;
    input.addMouseWheel(-6.f);
    stepWith(level, input);
    EXPECT_FALSE(level.isOverlapping(0));
    EXPECT_NEAR(turnBetween(0.f, level.getShapes()[0].body.angleDegrees), -90.f, 1e-3f);
}

TEST(Task4PushOut, HiddenOnlyTheHeldShapeMovesAndByItsMtv)
{
    // The third shape is held (Tab twice) and overlaps the first: Space moves it, by the MTV
    // and no further, and leaves the others where they are.
    RotatedLevel level = levelWithFrameworkSat({{{{100.f, 100.f}, {40.f, 40.f}, 0.f}, false},
                                                {{{400.f, 300.f}, {30.f, 10.f}, 0.f}, false},
                                                {{{150.f, 125.f}, {20.f, 20.f}, -30.f}, false}});
    press(level, sf::Keyboard::Key::Tab);
    press(level, sf::Keyboard::Key::Tab);
    ASSERT_EQ(level.getHeld(), 2u);
    ASSERT_TRUE(level.isOverlapping(2));
    const PairView* overFirst = nullptr;
    for (const PairView& pair : level.getPairs())
        if (pair.other == 0)
            overFirst = &pair;
    ASSERT_NE(overFirst, nullptr);
    ASSERT_TRUE(overFirst->overlapping);
    const hitbox::Vec2 expectedMove = overFirst->axis * -overFirst->gap;
    const hitbox::Vec2 before = level.getShapes()[2].body.center;

    press(level, sf::Keyboard::Key::Space);
    const hitbox::Vec2 moved = level.getShapes()[2].body.center - before;
    EXPECT_NEAR(moved.x, expectedMove.x, 1e-2f);
    EXPECT_NEAR(moved.y, expectedMove.y, 1e-2f);
    EXPECT_EQ(level.getShapes()[0].body.center, hitbox::Vec2(100.f, 100.f));
    EXPECT_EQ(level.getShapes()[1].body.center, hitbox::Vec2(400.f, 300.f));
    expectPushedOut(level);
}

TEST(Task4PushOut, HiddenAPushIntoAShapeListedEarlierGoesRoundAgain)
{
    // Out of the wall on the left (2 px to the right), which pushes it 1 px into the block
    // above on the right, listed before the wall: only a second round gets it out of that,
    // 0.8 px upwards (less than the 1 px sideways, which would go back into the wall).
    RotatedLevel level = levelWithFrameworkSat({axisAligned(0.f, 0.f, 20.f, 20.f),
                                                axisAligned(21.f, 19.2f, 100.f, 100.f),
                                                axisAligned(-50.f, -50.f, 2.f, 50.f)});
    ASSERT_TRUE(level.isOverlapping(0));
    press(level, sf::Keyboard::Key::Space);
    expectPushedOut(level);
    const hitbox::Vec2 center = level.getShapes()[0].body.center;
    EXPECT_NEAR(center.x, 12.f, 1e-3f);
    EXPECT_NEAR(center.y, 9.2f, 1e-3f);
}

// Edge rule: touching is not overlapping, so there is nothing to push out of.
TEST(Task4PushOut, HiddenAShapeThatOnlyTouchesStaysPut)
{
    RotatedLevel level = levelWithFrameworkSat({axisAligned(0.f, 0.f, 20.f, 20.f),
                                                axisAligned(20.f, 5.f, 60.f, 40.f),
                                                axisAligned(-30.f, 20.f, 10.f, 50.f)});
    ASSERT_FALSE(level.isOverlapping(0));
    press(level, sf::Keyboard::Key::Space);
    EXPECT_EQ(level.getShapes()[0].body.center, hitbox::Vec2(10.f, 10.f));
}
