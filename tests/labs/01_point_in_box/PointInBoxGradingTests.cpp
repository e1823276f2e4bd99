// Grading tests of lab 1 (point in box). Each suite is named after the task it checks
// (Task1..., Task2..., Task3...); README.md lists them. The level runs with no window. Each
// task's tests call that task's own step of update() (findBoxUnder, dragBox, windowToScene)
// and no other task's, so one mistake costs one task.
#include "labs/01_point_in_box/PointInBoxChecks.h"
#include "labs/LabTesting.h"

#include "PointInBoxLevel.h"

#include "hitbox/app/App.h"
#include "hitbox/geometry/Shapes.h"

#include <SFML/Graphics/View.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace
{

using namespace pointinboxchecks;

// A point inside box `index`, clear of every box drawn after it (which would cover it).
sf::Vector2f uncoveredPointOf(const PointInBoxLevel& level, int index)
{
    const hitbox::Box box = hitbox::toBox(level.getBox(index).getCollisionBox());
    for (float fy = 0.1f; fy < 1.f; fy += 0.1f)
        for (float fx = 0.1f; fx < 1.f; fx += 0.1f)
        {
            const sf::Vector2f point{box.left + box.width * fx, box.top + box.height * fy};
            bool covered = false;
            for (int later = index + 1; later < level.getBoxCount(); ++later)
            {
                // A few pixels clear of the covering box, so rounding cannot land on it.
                const hitbox::Box box = hitbox::toBox(level.getBox(later).getCollisionBox());
                const sf::FloatRect near({box.left - 4.f, box.top - 4.f},
                                         {box.width + 8.f, box.height + 8.f});
                covered = covered || near.contains(point);
            }
            if (!covered)
                return point;
        }
    ADD_FAILURE() << "box " << index << " is covered completely";
    return hitbox::toSfml(hitbox::centerOf(box));
}

// Where the mouse is in world coordinates when it is at `pixel` in a window of
// `windowSize` pixels: what the window does with sf::RenderWindow::mapPixelToCoords and
// the letterboxed view (hitbox/app/App.h), worked out here without opening a window.
sf::Vector2f pixelToWorld(sf::Vector2i pixel, sf::Vector2u windowSize, sf::Vector2f world)
{
    sf::View view(sf::FloatRect({0.f, 0.f}, world));
    view.setViewport(hitbox::letterboxViewport(windowSize, world));
    const hitbox::Box viewport = hitbox::toBox(view.getViewport());
    const sf::Vector2f size(windowSize);
    const sf::Vector2f normalized{
        -1.f + 2.f * (pixel.x - viewport.left * size.x) / (viewport.width * size.x),
        1.f - 2.f * (pixel.y - viewport.top * size.y) / (viewport.height * size.y)};
    return view.getInverseTransform().transformPoint(normalized);
}

// The pixel of a window of `windowSize` where world point `point` is drawn.
sf::Vector2i worldToPixel(sf::Vector2f point, sf::Vector2u windowSize, sf::Vector2f world)
{
    const hitbox::Box viewport = hitbox::toBox(hitbox::letterboxViewport(windowSize, world));
    const sf::Vector2f size(windowSize);
    return {static_cast<int>(viewport.left * size.x + point.x / world.x * viewport.width * size.x),
            static_cast<int>(viewport.top * size.y + point.y / world.y * viewport.height * size.y)};
}

// An empty spot: the top-left corner of the scene has no box.
const sf::Vector2f emptySpot{20.f, 20.f};

} // namespace

TEST(Task1FindTheBoxUnderTheMouse, EveryBoxIsHoveredWhenTheMouseIsOverIt)
{
    PointInBoxLevel level;
    ASSERT_GE(level.getBoxCount(), 2);
    for (int index = 0; index < level.getBoxCount(); ++index)
        EXPECT_EQ(level.findBoxUnder(uncoveredPointOf(level, index)), index)
            << "mouse over box " << index;
}

TEST(Task1FindTheBoxUnderTheMouse, InAResizedWindowTheHoveredBoxIsTheOneUnderTheMouse)
{
    // A tall window: the world is letterboxed with bars above and below, and window pixels
    // are no longer world pixels. Input gives the mouse in world coordinates.
    PointInBoxLevel level;
    const sf::Vector2u windowSize{700, 900};
    const sf::Vector2f world = level.getWorldSize();
    for (int index = 0; index < level.getBoxCount(); ++index)
    {
        const sf::Vector2i pixel = worldToPixel(uncoveredPointOf(level, index), windowSize, world);
        EXPECT_EQ(level.findBoxUnder(pixelToWorld(pixel, windowSize, world)), index)
            << "mouse at pixel (" << pixel.x << ", " << pixel.y << ") of a 700 x 900 window";
    }
}

TEST(Task1FindTheBoxUnderTheMouse, NothingIsHoveredOverEmptySpace)
{
    PointInBoxLevel level;
    EXPECT_EQ(level.findBoxUnder(emptySpot), PointInBoxLevel::noBox);
}

TEST(Task1FindTheBoxUnderTheMouse, JustInsideTheCornerIsHoveredJustOutsideIsNot)
{
    PointInBoxLevel level;
    const hitbox::Box box = hitbox::toBox(level.getBox(0).getCollisionBox());
    EXPECT_EQ(level.findBoxUnder({box.left + 1.f, box.top + 1.f}), 0);
    EXPECT_EQ(level.findBoxUnder({box.left - 1.f, box.top + 1.f}), PointInBoxLevel::noBox);
    EXPECT_NE(level.findBoxUnder({hitbox::rightOf(box) + 1.f, hitbox::bottomOf(box) - 1.f}), 0);
}

TEST(Task1FindTheBoxUnderTheMouse, APointExactlyOnAnEdgeIsNotInside)
{
    // The edge rule of Collision::checkBoundingBox (hitbox/geometry/Overlap.h): touching is
    // not colliding, so a point exactly on an edge is outside; half a pixel in, it is inside.
    PointInBoxLevel level;
    const hitbox::Box box = hitbox::toBox(level.getBox(0).getCollisionBox());
    const sf::Vector2f middle = hitbox::toSfml(hitbox::centerOf(box));
    const float right = hitbox::rightOf(box);
    const float bottom = hitbox::bottomOf(box);
    const sf::Vector2f onEdges[] = {
        {box.left, middle.y}, {right, middle.y}, {middle.x, box.top}, {middle.x, bottom}};
    const sf::Vector2f inwards[] = {{0.5f, 0.f}, {-0.5f, 0.f}, {0.f, 0.5f}, {0.f, -0.5f}};
    for (int edge = 0; edge < 4; ++edge)
    {
        EXPECT_NE(level.findBoxUnder(onEdges[edge]), 0)
            << "the point " << labtesting::text(onEdges[edge]) << " on an edge of box 0";
        EXPECT_EQ(level.findBoxUnder(onEdges[edge] + inwards[edge]), 0)
            << "half a pixel inside from " << labtesting::text(onEdges[edge]);
    }
}

TEST(Task1FindTheBoxUnderTheMouse, WhereBoxesOverlapTheOneDrawnOnTopIsHovered)
{
    PointInBoxLevel level;
    // Find two overlapping boxes; the later one is drawn over the earlier one.
    for (int first = 0; first < level.getBoxCount(); ++first)
        for (int second = first + 1; second < level.getBoxCount(); ++second)
        {
            const hitbox::Box a = hitbox::toBox(level.getBox(first).getCollisionBox());
            const hitbox::Box b = hitbox::toBox(level.getBox(second).getCollisionBox());
            const float left = std::max(a.left, b.left);
            const float top = std::max(a.top, b.top);
            const float right = std::min(hitbox::rightOf(a), hitbox::rightOf(b));
            const float bottom = std::min(hitbox::bottomOf(a), hitbox::bottomOf(b));
            if (left < right && top < bottom)
            {
                const sf::Vector2f both{(left + right) / 2.f, (top + bottom) / 2.f};
                EXPECT_GE(level.findBoxUnder(both), second)
                    << "boxes " << first << " and " << second << " overlap at "
                    << labtesting::text(both);
                return;
            }
        }
    FAIL() << "the level should have two overlapping boxes";
}

TEST(Task2DragTheSelectedBox, PressingOverABoxSelectsIt)
{
    Player player;
    player.moveMouseTo(uncoveredPointOf(player.level, 1));
    player.pressLeft();
    EXPECT_EQ(player.level.getSelectedBox(), 1);
}

TEST(Task2DragTheSelectedBox, PressingOverEmptySpaceSelectsNothing)
{
    Player player;
    player.moveMouseTo(emptySpot);
    player.pressLeft();
    EXPECT_EQ(player.level.getSelectedBox(), PointInBoxLevel::noBox);
}

TEST(Task2DragTheSelectedBox, TheBoxMovesExactlyAsFarAsTheMouse)
{
    Player player;
    const sf::Vector2f grab = uncoveredPointOf(player.level, 1);
    const sf::Vector2f start = player.level.getBox(1).getPosition();
    player.moveMouseTo(grab);
    player.pressLeft();
    // Drag in small steps, the way a real mouse moves; the box stays under it.
    const sf::Vector2f drag{180.f, -60.f};
    for (int i = 1; i <= 10; ++i)
        player.moveMouseTo(grab + drag * (i / 10.f));
    EXPECT_VEC_NEAR(player.level.getBox(1).getPosition(), start + drag, 0.01f)
        << "the grabbed point stays under the mouse: the box must not jump to the mouse";
}

TEST(Task2DragTheSelectedBox, ReleasingDropsTheBox)
{
    Player player;
    const sf::Vector2f grab = uncoveredPointOf(player.level, 1);
    player.moveMouseTo(grab);
    player.pressLeft();
    player.moveMouseTo(grab + sf::Vector2f{50.f, 0.f});
    player.releaseLeft();
    EXPECT_EQ(player.level.getSelectedBox(), PointInBoxLevel::noBox);
    const sf::Vector2f dropped = player.level.getBox(1).getPosition();
    player.moveMouseTo(grab + sf::Vector2f{200.f, 100.f});
    EXPECT_VEC_NEAR(player.level.getBox(1).getPosition(), dropped, 0.01f)
        << "after the release the mouse moves on alone";
}

TEST(Task2DragTheSelectedBox, DraggingOverAnotherBoxKeepsHoldOfTheFirst)
{
    Player player;
    const sf::Vector2f start = uncoveredPointOf(player.level, 0);
    player.moveMouseTo(start);
    player.pressLeft();
    const sf::Vector2f target = uncoveredPointOf(player.level, 1);
    for (int i = 1; i <= 10; ++i)
        player.moveMouseTo(start * (1.f - i / 10.f) + target * (i / 10.f));
    EXPECT_EQ(player.level.getSelectedBox(), 0);
}

TEST(Task3MouseInTheZoomedScene, AfterZoomingTheHoveredBoxIsTheOneDrawnUnderTheMouse)
{
    Player player;
    player.zoom(2);
    ASSERT_GT(player.level.getZoom(), 1.2f) << "the mouse wheel should zoom in";
    int checked = 0;
    for (int index = 0; index < player.level.getBoxCount(); ++index)
    {
        const sf::Vector2f inBox = uncoveredPointOf(player.level, index);
        const sf::Vector2f onScreen = player.onScreen(inBox);
        const sf::Vector2f window = player.level.getWorldSize();
        if (onScreen.x < 0.f || onScreen.y < 0.f || onScreen.x > window.x || onScreen.y > window.y)
            continue; // zoomed out of sight
        EXPECT_VEC_NEAR(player.level.windowToScene(onScreen), inBox, 0.05f)
            << "box " << index << " is drawn at " << labtesting::text(onScreen) << " in the window";
        ++checked;
    }
    EXPECT_GE(checked, 2) << "some boxes should stay on screen when zoomed in twice";
}

TEST(Task3MouseInTheZoomedScene, AfterZoomingOutEmptySpaceIsStillEmpty)
{
    Player player;
    player.zoom(-1);
    ASSERT_LT(player.level.getZoom(), 1.f) << "the mouse wheel should zoom out";
    // Zoomed out, the box at the top-left corner is drawn away from the corner: pointing at
    // the corner of the window points at nothing.
    const sf::Vector2f inBox = uncoveredPointOf(player.level, 0);
    EXPECT_VEC_NEAR(player.level.windowToScene(player.onScreen(inBox)), inBox, 0.05f);
    const sf::Vector2f corner = player.level.windowToScene({5.f, 5.f});
    EXPECT_EQ(boxAt(player.level, corner), PointInBoxLevel::noBox)
        << "the window's corner is scene point " << labtesting::text(corner);
}

TEST(Task3MouseInTheZoomedScene, AfterZoomingTheDraggedBoxStaysUnderTheMouse)
{
    // Zoomed in, the mouse moves further on screen than the box it drags moves in the scene:
    // the scene moves by the mouse's move divided by the zoom, so the grabbed point stays
    // exactly under the mouse.
    Player player;
    player.zoom(1);
    const sf::Vector2f grabScene = uncoveredPointOf(player.level, 1);
    const sf::Vector2f grab = player.onScreen(grabScene);
    const sf::Vector2f end = grab + sf::Vector2f{-120.f, 90.f};
    const sf::Vector2f endScene = player.level.windowToScene(end);
    EXPECT_VEC_NEAR(endScene - player.level.windowToScene(grab),
                    (end - grab) / player.level.getZoom(), 0.05f);
    EXPECT_VEC_NEAR(player.onScreen(endScene), end, 0.05f)
        << "the scene point under the mouse is drawn under the mouse";
}
