// Hidden variants of lab 1's grading tests: the same behaviour as PointInBoxGradingTests.cpp
// and PointInPolygonGradingTests.cpp with other points, boxes, zooms and polygons. The
// instructor's build and the class grader run them; the student handout leaves
// tests/labs-hidden/ out, so no one can tune an answer to them. As in the visible tests, each
// task's tests call only that task's step (findBoxUnder, dragBox, windowToScene,
// isInsidePolygon), so one mistake costs one task.
#include "labs/01_point_in_box/PointInBoxChecks.h"
#include "labs/LabTesting.h"

#include "PointInBoxLevel.h"
#include "PointInPolygon.h"

#include "hitbox/geometry/Shapes.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/System/Vector2.hpp>

#include <gtest/gtest.h>

#include <cstddef>
#include <initializer_list>
#include <vector>

namespace
{

using namespace pointinboxchecks;

// A point of box `index` near its bottom-right corner (the visible tests grab near the
// top-left), with that box on top for a few pixels all round, so rounding cannot land on
// another box or on an edge.
sf::Vector2f farPointOf(const PointInBoxLevel& level, int index)
{
    const hitbox::Box box = hitbox::toBox(level.getBox(index).getCollisionBox());
    for (float fy = 0.85f; fy > 0.1f; fy -= 0.05f)
        for (float fx = 0.85f; fx > 0.1f; fx -= 0.05f)
        {
            const sf::Vector2f point{box.left + box.width * fx, box.top + box.height * fy};
            bool clear = true;
            for (const sf::Vector2f nudge :
                 {sf::Vector2f{0.f, 0.f}, sf::Vector2f{4.f, 4.f}, sf::Vector2f{-4.f, 4.f},
                  sf::Vector2f{4.f, -4.f}, sf::Vector2f{-4.f, -4.f}})
                clear = clear && boxAt(level, point + nudge) == index;
            if (clear)
                return point;
        }
    ADD_FAILURE() << "box " << index << " is covered completely";
    return hitbox::toSfml(hitbox::centerOf(box));
}

// An "L" with whole-number corners, partly at negative x: a tall arm on the left and a foot
// along the bottom, with a notch (inside its bounding box) above the foot on the right.
const Corners lShape{{-37.f, 12.f}, {13.f, 12.f}, {13.f, 42.f},
                     {63.f, 42.f},  {63.f, 62.f}, {-37.f, 62.f}};
// A chevron pointing right: its tip (-20, 0) and its concave corner (-40, 0) lie on one
// horizontal line, and its edges slope 1 in 2 and 1 in 1, where float arithmetic is exact.
const Corners chevron{{-60.f, -20.f}, {-20.f, 0.f}, {-60.f, 20.f}, {-40.f, 0.f}};

} // namespace

TEST(Task1FindTheBoxUnderTheMouse, HiddenAGridOverTheWholeSceneFindsTheTopBoxEverywhere)
{
    // Thousands of points at an odd spacing, over every box, every overlap and the empty
    // space between them (and some exactly on an edge): an answer tuned to a few points
    // cannot match them all.
    PointInBoxLevel level;
    const sf::Vector2f world = level.getWorldSize();
    std::vector<bool> seen(static_cast<std::size_t>(level.getBoxCount()), false);
    int wrong = 0;
    for (float y = 4.f; y < world.y; y += 11.f)
        for (float x = 7.f; x < world.x; x += 13.f)
        {
            const sf::Vector2f point{x, y};
            const int expected = boxAt(level, point);
            const int found = level.findBoxUnder(point);
            if (expected != PointInBoxLevel::noBox)
                seen[static_cast<std::size_t>(expected)] = true;
            if (found != expected && ++wrong <= 5)
                ADD_FAILURE() << "at " << labtesting::text(point) << " findBoxUnder gives " << found
                              << ", the box on top there is " << expected;
        }
    EXPECT_EQ(wrong, 0) << "points where the wrong box (or none) was found";
    for (std::size_t index = 0; index < seen.size(); ++index)
        EXPECT_TRUE(seen[index]) << "the grid should reach box " << index;
}

TEST(Task1FindTheBoxUnderTheMouse, HiddenOnABoxsEdgeTheBoxBelowItOrNoneIsFound)
{
    // The edge rule on every box, at corners and at odd places along each edge, not only in
    // the middle of box 0's edges: a point exactly on an edge is outside that box, so there
    // the box underneath (or none) is the answer; a quarter pixel in, the top box there is.
    PointInBoxLevel level;
    int onAnotherBox = 0;
    for (int index = 0; index < level.getBoxCount(); ++index)
    {
        const hitbox::Box box = hitbox::toBox(level.getBox(index).getCollisionBox());
        const float right = hitbox::rightOf(box);
        const float bottom = hitbox::bottomOf(box);
        for (const float along : {0.f, 0.37f, 0.81f, 1.f})
        {
            const float x = box.left + box.width * along;
            const float y = box.top + box.height * along;
            const sf::Vector2f onEdges[] = {{box.left, y}, {right, y}, {x, box.top}, {x, bottom}};
            const sf::Vector2f inwards[] = {
                {0.25f, 0.f}, {-0.25f, 0.f}, {0.f, 0.25f}, {0.f, -0.25f}};
            for (int edge = 0; edge < 4; ++edge)
            {
                const sf::Vector2f onEdge = onEdges[edge];
                const int expected = boxAt(level, onEdge);
                onAnotherBox += expected != PointInBoxLevel::noBox ? 1 : 0;
                EXPECT_EQ(level.findBoxUnder(onEdge), expected)
                    << labtesting::text(onEdge) << " is on an edge of box " << index;
                if (along == 0.f || along == 1.f)
                    continue; // at a corner a step along one axis stays on the other edge
                const sf::Vector2f inside = onEdge + inwards[edge];
                EXPECT_EQ(level.findBoxUnder(inside), boxAt(level, inside))
                    << "a quarter pixel inside box " << index << " from "
                    << labtesting::text(onEdge);
            }
        }
    }
    EXPECT_GT(onAnotherBox, 0) << "some edge should lie over another box";
}

TEST(Task2DragTheSelectedBox, HiddenTheTopBoxGrabbedNearItsCornerMovesExactlyAsFarAsTheMouse)
{
    // Another box, grabbed near another corner, dragged the other way in uneven steps over
    // the boxes below it: the box keeps its grab offset and stays held until the release.
    Player player;
    const int top = player.level.getBoxCount() - 1;
    const sf::Vector2f grab = farPointOf(player.level, top);
    const sf::Vector2f start = player.level.getBox(top).getPosition();
    player.moveMouseTo(grab);
    player.pressLeft();
    ASSERT_EQ(player.level.getSelectedBox(), top);
    const sf::Vector2f drag{-237.5f, 161.25f};
    for (int i = 1; i <= 7; ++i)
        player.moveMouseTo(grab + drag * (static_cast<float>(i * i) / 49.f));
    EXPECT_EQ(player.level.getSelectedBox(), top) << "still held after passing other boxes";
    EXPECT_VEC_NEAR(player.level.getBox(top).getPosition(), start + drag, 0.01f)
        << "the point grabbed stays under the mouse";
    player.releaseLeft();
    player.moveMouseTo(grab + sf::Vector2f{31.f, -77.f});
    EXPECT_EQ(player.level.getSelectedBox(), PointInBoxLevel::noBox);
    EXPECT_VEC_NEAR(player.level.getBox(top).getPosition(), start + drag, 0.01f)
        << "dropped where it was let go";
}

TEST(Task2DragTheSelectedBox, HiddenASecondGrabTakesItsOwnOffsetAndLeavesTheFirstBoxBehind)
{
    // Two boxes dragged one after the other: the second grab picks its own box and its own
    // offset, and the first box stays where it was dropped.
    Player player;
    const int first = 2;
    const int second = 4;
    const sf::Vector2f firstStart = player.level.getBox(first).getPosition();
    const sf::Vector2f secondStart = player.level.getBox(second).getPosition();
    const sf::Vector2f firstGrab = farPointOf(player.level, first);
    const sf::Vector2f firstDrag{-93.f, 41.5f};
    player.moveMouseTo(firstGrab);
    player.pressLeft();
    for (int i = 1; i <= 4; ++i)
        player.moveMouseTo(firstGrab + firstDrag * (static_cast<float>(i) / 4.f));
    player.releaseLeft();

    const sf::Vector2f secondGrab = farPointOf(player.level, second);
    const sf::Vector2f secondDrag{57.75f, 66.f};
    player.moveMouseTo(secondGrab);
    player.pressLeft();
    EXPECT_EQ(player.level.getSelectedBox(), second);
    for (int i = 1; i <= 5; ++i)
        player.moveMouseTo(secondGrab + secondDrag * (static_cast<float>(i) / 5.f));
    EXPECT_VEC_NEAR(player.level.getBox(second).getPosition(), secondStart + secondDrag, 0.01f)
        << "the second box keeps the offset it was grabbed at, not the first one's";
    EXPECT_VEC_NEAR(player.level.getBox(first).getPosition(), firstStart + firstDrag, 0.01f)
        << "the first box stays where it was dropped";
}

TEST(Task2DragTheSelectedBox, HiddenAButtonHeldDownSinceEmptySpacePicksUpNoBox)
{
    // Only the step the button goes down picks a box: sweeping onto a box with the button
    // already held picks up nothing and moves nothing.
    Player player;
    const sf::Vector2f empty{1150.f, 640.f};
    ASSERT_EQ(boxAt(player.level, empty), PointInBoxLevel::noBox);
    const int target = 6;
    const sf::Vector2f start = player.level.getBox(target).getPosition();
    const sf::Vector2f over = farPointOf(player.level, target);
    player.moveMouseTo(empty);
    player.pressLeft();
    for (int i = 1; i <= 6; ++i)
        player.moveMouseTo(empty + (over - empty) * (static_cast<float>(i) / 6.f));
    player.moveMouseTo(over + sf::Vector2f{-40.f, -25.f});
    EXPECT_EQ(player.level.getSelectedBox(), PointInBoxLevel::noBox);
    EXPECT_VEC_NEAR(player.level.getBox(target).getPosition(), start, 0.01f);
}

TEST(Task3MouseInTheZoomedScene, HiddenZoomedOutTwiceEveryWindowPointGoesBackThroughTheCamera)
{
    // Zoomed out two notches (the visible tests zoom two in and one out), at window points
    // all over, corners included: the scene point found is the one the camera draws under
    // the mouse, and the window's corners show scene points outside the scene. Only undoing
    // the camera itself gets every point right at a zoom the visible tests never use.
    Player player;
    player.zoom(-2);
    const float zoom = player.level.getZoom();
    ASSERT_LT(zoom, 0.7f) << "two notches out";
    const sf::Vector2f world = player.level.getWorldSize();
    const sf::Vector2f middle = world / 2.f;
    for (float fy = 0.f; fy <= 1.f; fy += 0.25f)
        for (float fx = 0.f; fx <= 1.f; fx += 0.2f)
        {
            const sf::Vector2f window{world.x * fx + 3.f, world.y * fy - 2.f};
            const sf::Vector2f scene = player.level.windowToScene(window);
            EXPECT_VEC_NEAR(player.level.getCamera().transformPoint(scene), window, 0.05f)
                << "the mouse at " << labtesting::text(window) << " in the window";
            EXPECT_VEC_NEAR(scene, middle + (window - middle) / zoom, 0.05f)
                << "the mouse at " << labtesting::text(window) << " in the window";
        }
    const sf::Vector2f corner = player.level.windowToScene({0.f, 0.f});
    EXPECT_LT(corner.x, 0.f);
    EXPECT_LT(corner.y, 0.f);
}

TEST(Task3MouseInTheZoomedScene, HiddenAtTheLargestZoomTheMouseMovesAThirdAsFarInTheScene)
{
    // Zoomed in to the limit (the wheel turned past it, a zoom no visible test reaches): the
    // window shows the middle third of the scene, and a mouse move is a scene move of a third
    // of it, in another direction than the visible drag.
    Player player;
    player.zoom(12);
    const float zoom = player.level.getZoom();
    ASSERT_FLOAT_EQ(zoom, PointInBoxLevel::maxZoom);
    const sf::Vector2f world = player.level.getWorldSize();
    const sf::Vector2f middle = world / 2.f;
    EXPECT_VEC_NEAR(player.level.windowToScene(middle), middle, 0.05f)
        << "the camera zooms about the middle of the window";
    EXPECT_VEC_NEAR(player.level.windowToScene({0.f, 0.f}), middle - middle / zoom, 0.05f);
    EXPECT_VEC_NEAR(player.level.windowToScene(world), middle + middle / zoom, 0.05f);
    const sf::Vector2f from{811.f, 142.5f};
    const sf::Vector2f move{-75.f, 48.f};
    EXPECT_VEC_NEAR(player.level.windowToScene(from + move) - player.level.windowToScene(from),
                    move / zoom, 0.05f);
}

TEST(Task4PointInPolygon, HiddenAnLShapeAtNegativeCoordinatesHasANotch)
{
    // A concave shape other than the C, partly left of x = 0, either way round: the arm and
    // the foot are inside, the notch and the space around are not; a ray along the notch's
    // floor passes its concave corner. An answer tuned to the square and the C misses it.
    for (const Corners& shape : {lShape, reversed(lShape)})
    {
        EXPECT_TRUE(isInsidePolygon(shape, {-20.f, 30.f}));   // the arm
        EXPECT_TRUE(isInsidePolygon(shape, {40.f, 52.f}));    // the foot
        EXPECT_TRUE(isInsidePolygon(shape, {-36.5f, 61.5f})); // the outer corner, just in
        EXPECT_TRUE(isInsidePolygon(shape, {0.f, 42.f}));     // level with the concave corner
        EXPECT_FALSE(isInsidePolygon(shape, {40.f, 25.f}));   // in the notch
        EXPECT_FALSE(isInsidePolygon(shape, {40.f, 12.f}));   // level with the arm's top
        EXPECT_FALSE(isInsidePolygon(shape, {-50.f, 42.f}));  // left, the ray crosses twice
        EXPECT_FALSE(isInsidePolygon(shape, {70.f, 52.f}));   // right of the foot
        EXPECT_FALSE(isInsidePolygon(shape, {0.f, 70.f}));    // below
        // On the left edge, a 64th of a pixel from the bottom-left corner: still the edge.
        EXPECT_FALSE(isInsidePolygon(shape, {-37.f, 62.f - 0.015625f}));
    }
}

TEST(Task4PointInPolygon, HiddenOnTheEdgesAndCornersOfAChevronIsOutside)
{
    // The edge rule on sloping edges and on a concave corner, and rays passing exactly
    // through the tip and the concave corner, which must count once each, either way round.
    for (const Corners& shape : {chevron, reversed(chevron)})
    {
        EXPECT_TRUE(isInsidePolygon(shape, {-30.f, 0.f}));   // between the two corners
        EXPECT_TRUE(isInsidePolygon(shape, {-35.f, -5.f}));  // the upper wing
        EXPECT_TRUE(isInsidePolygon(shape, {-35.f, 5.f}));   // the lower wing
        EXPECT_FALSE(isInsidePolygon(shape, {-50.f, 0.f}));  // in the notch, ray through both
        EXPECT_FALSE(isInsidePolygon(shape, {-65.f, 0.f}));  // left of it all
        EXPECT_FALSE(isInsidePolygon(shape, {-10.f, 0.f}));  // right of the tip
        EXPECT_FALSE(isInsidePolygon(shape, {-50.f, -5.f})); // in the notch, off the line
        EXPECT_FALSE(isInsidePolygon(shape, {-30.f, -5.f})); // on the upper outer edge
        EXPECT_FALSE(isInsidePolygon(shape, {-50.f, 10.f})); // on the lower inner edge
        EXPECT_FALSE(isInsidePolygon(shape, {-20.f, 0.f}));  // the tip
        EXPECT_FALSE(isInsidePolygon(shape, {-40.f, 0.f}));  // the concave corner
        EXPECT_FALSE(isInsidePolygon(shape, {-60.f, 20.f})); // a back corner
        // On the upper inner edge, a 128th of a pixel from the concave corner.
        EXPECT_FALSE(isInsidePolygon(shape, {-40.f - 0.0078125f, -0.0078125f}));
    }
}

TEST(Task4PointInPolygon, HiddenTheLevelsStarIsInsideUpToItsTipsAndOutsideInItsGaps)
{
    // The level's star at other distances: nearly out to each tip and to each inner corner
    // is inside, just past a tip or an inner corner is outside.
    const PointInBoxLevel level;
    const Corners& star = level.getStar();
    ASSERT_EQ(star.size(), 10u);
    const sf::Vector2f middle = middleOf(star);
    for (std::size_t corner = 0; corner < star.size(); ++corner)
    {
        const sf::Vector2f out = star[corner] - middle;
        const bool tip = corner % 2 == 0;
        EXPECT_TRUE(isInsidePolygon(star, middle + out * (tip ? 0.85f : 0.9f)))
            << "short of corner " << corner;
        EXPECT_FALSE(isInsidePolygon(star, middle + out * (tip ? 1.05f : 1.15f)))
            << "past corner " << corner;
    }
}
