// Helpers of lab 6's grading tests: boxes, the SAT worked out without task 1, levels that use
// the framework's SAT, a step of input and the push-out check. Both the grading tests
// (RotatedGradingTests.cpp) and their hidden variants use them: one home for each.
#pragma once

#include "RotatedLevel.h"
#include "Sat.h"

#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Vec2.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace rotatedchecks
{

// A box turned `degrees` clockwise, its corners from the framework so no task's code makes them.
inline hitbox::Polygon box(hitbox::Vec2 center, hitbox::Vec2 halfSize, float degrees)
{
    return hitbox::toPolygon(hitbox::OrientedBox{center, halfSize, degrees});
}

// An unturned, undragged box given by its sides, so a scene's touching edges are exact.
inline Shape axisAligned(float left, float top, float right, float bottom)
{
    return Shape{{{(left + right) / 2.f, (top + bottom) / 2.f},
                  {(right - left) / 2.f, (bottom - top) / 2.f},
                  0.f},
                 false};
}

// Both polygons' shadows on all their edge normals, worked out here: task 2's tests need no task 1.
inline std::vector<AxisShadows> axesOf(const hitbox::Polygon& a, const hitbox::Polygon& b)
{
    const auto shadow = [](const hitbox::Polygon& polygon, hitbox::Vec2 axis)
    {
        Shadow onAxis{hitbox::dot(polygon.points[0], axis), hitbox::dot(polygon.points[0], axis)};
        for (const hitbox::Vec2& point : polygon.points)
        {
            onAxis.min = std::min(onAxis.min, hitbox::dot(point, axis));
            onAxis.max = std::max(onAxis.max, hitbox::dot(point, axis));
        }
        return onAxis;
    };
    std::vector<AxisShadows> axes;
    for (const hitbox::Polygon* polygon : {&a, &b})
        for (std::size_t i = 0; i < polygon->points.size(); ++i)
        {
            const hitbox::Vec2 edge =
                polygon->points[(i + 1) % polygon->points.size()] - polygon->points[i];
            const hitbox::Vec2 axis = hitbox::unitVectorOr(hitbox::perpendicular(edge), {1.f, 0.f});
            axes.push_back({axis, shadow(a, axis), shadow(b, axis)});
        }
    return axes;
}

// Task 2's answer (chooseAxis) for two polygons, with no task 1 code on the way to it.
inline SatResult sat(const hitbox::Polygon& a, const hitbox::Polygon& b)
{
    return chooseAxis(axesOf(a, b));
}

// A level whose box pairs are tested by the framework's SAT, so tasks 3 and 4 need no task 1 or 2.
inline RotatedLevel levelWithFrameworkSat(std::vector<Shape> shapes)
{
    RotatedLevel level(std::move(shapes));
    level.setFrameworkSat(true);
    level.update(hitbox::stepSeconds);
    return level;
}

// One step of the level as the window runs it, so a test sees what the player's input does.
inline void stepWith(RotatedLevel& level, hitbox::Input& input)
{
    level.handleInput(input, hitbox::stepSeconds);
    level.update(hitbox::stepSeconds);
    input.update();
}

// A push out leaves the held shape overlapping nothing, exactly: pushOutOffset rounds outward.
inline void expectPushedOut(const RotatedLevel& level)
{
    for (const PairView& pair : level.getPairs())
        EXPECT_FALSE(pair.overlapping) << "still overlapping shape " << pair.other << " by "
                                       << -pair.gap << " px after the push";
}

} // namespace rotatedchecks
