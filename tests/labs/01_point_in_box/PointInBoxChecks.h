// Helpers of lab 1's grading tests: the top box under a point worked out from the boxes
// themselves, a player dragging boxes with the mouse, and polygons turned round. Both the
// grading tests (PointInBoxGradingTests.cpp, PointInPolygonGradingTests.cpp) and their hidden
// variants use them: one home for each.
#pragma once

#include "PointInBoxLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/geometry/Shapes.h"
#include "hitbox/sfml/Conversions.h"

#include <SFML/System/Vector2.hpp>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace pointinboxchecks
{

// The top box containing the scene point, or noBox (a point on an edge is outside, the edge
// rule): the answer task 1's tests compare with, and what tasks 2 and 3 use instead of task 1.
inline int boxAt(const PointInBoxLevel& level, sf::Vector2f point)
{
    for (int index = level.getBoxCount() - 1; index >= 0; --index)
    {
        const hitbox::Box box = hitbox::toBox(level.getBox(index).getCollisionBox());
        if (point.x > box.left && point.x < hitbox::rightOf(box) && point.y > box.top &&
            point.y < hitbox::bottomOf(box))
            return index;
    }
    return PointInBoxLevel::noBox;
}

// A player at the mouse (task 2): moves it, presses and releases the left button, one step
// at a time. Each step hands dragBox the box under the mouse as boxAt finds it (so task 2
// needs no task 1), with the scene unzoomed (so it needs no task 3).
struct Player
{
    PointInBoxLevel level;
    hitbox::Input input;
    sf::Vector2f mouse;

    void step()
    {
        level.handleInput(input, hitbox::stepSeconds);
        level.dragBox(boxAt(level, mouse), mouse);
        input.update();
    }
    void moveMouseTo(sf::Vector2f scenePoint)
    {
        mouse = scenePoint;
        step();
    }
    void pressLeft()
    {
        input.setMouseLDown(true);
        step();
    }
    void releaseLeft()
    {
        input.setMouseLDown(false);
        step();
    }
    // Zooms with the mouse wheel (handleInput's own work, no task's).
    void zoom(int notches)
    {
        for (int notch = 0; notch < std::abs(notches); ++notch)
        {
            input.addMouseWheel(notches > 0 ? 1.f : -1.f);
            level.handleInput(input, hitbox::stepSeconds);
            input.update();
        }
    }
    // Where a scene point is drawn in the window (through the level's camera).
    sf::Vector2f onScreen(sf::Vector2f scenePoint) const
    {
        return level.getCamera().transformPoint(scenePoint);
    }
};

// A polygon's corners, in order (task 4).
using Corners = std::vector<sf::Vector2f>;

// The same polygon the other way round: the inside must not depend on the winding.
inline Corners reversed(Corners corners)
{
    std::reverse(corners.begin(), corners.end());
    return corners;
}

// The average of a polygon's corners: the middle of the level's star, from which each tip
// and each gap lies outwards.
inline sf::Vector2f middleOf(const Corners& corners)
{
    sf::Vector2f middle;
    for (const sf::Vector2f corner : corners)
        middle += corner / static_cast<float>(corners.size());
    return middle;
}

} // namespace pointinboxchecks
