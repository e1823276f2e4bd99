#include "Sat.h"

#include "hitbox/geometry/Vec2.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace
{
// The unit normals of a polygon's edges: the axes its edges could be separated along.
std::vector<hitbox::Vec2> edgeNormals(const hitbox::Polygon& polygon)
{
    std::vector<hitbox::Vec2> normals;
    const std::size_t count = polygon.points.size();
    for (std::size_t i = 0; i < count; ++i)
    {
        const hitbox::Vec2 edge = polygon.points[(i + 1) % count] - polygon.points[i];
        if (edge != hitbox::Vec2{})
            normals.push_back(hitbox::unitVectorOr(hitbox::perpendicular(edge), {1.f, 0.f}));
    }
    return normals;
}
} // namespace

Shadow projectOnto(const hitbox::Polygon& polygon, hitbox::Vec2 axis)
{
    // BEGIN TASK 1: the shadow of the polygon on the axis
    // Each corner lands at dot(corner, axis) along the axis; the shadow runs from the
    // smallest to the largest of those.
    Shadow onAxis;
    for (std::size_t i = 0; i < polygon.points.size(); ++i)
    {
        const float along = hitbox::dot(polygon.points[i], axis);
        if (i == 0 || along < onAxis.min)
            onAxis.min = along;
        if (i == 0 || along > onAxis.max)
            onAxis.max = along;
    }
    return onAxis;
    // STARTER TASK 1
    // static_cast<void>(polygon); // (these two lines only keep the compiler quiet:
    // static_cast<void>(axis);    //  delete them when you write the projection)
    // return Shadow{};
    // END TASK 1
}

// [slide:lab06-sat-draw]
SatResult chooseAxis(const std::vector<AxisShadows>& axes)
{
    // BEGIN TASK 2: try every axis; keep the largest gap (or, with none, the least overlap)
    SatResult best{false, {}, -std::numeric_limits<float>::infinity()};
    for (const AxisShadows& onAxis : axes)
    {
        // Two ways out along this axis: A forwards past B's end, or backwards past its start.
        const float forwards = onAxis.b.max - onAxis.a.min;
        const float backwards = onAxis.a.max - onAxis.b.min;
        const float gap = -std::min(forwards, backwards);
        if (gap > best.gap)
            best = {gap >= 0.f, forwards < backwards ? onAxis.axis : -onAxis.axis, gap};
    }
    return best;
    // STARTER TASK 2
    // static_cast<void>(axes); // (only keeps the compiler quiet: delete it)
    // return SatResult{};
    // END TASK 2
}
// [/slide]

SatResult separatingAxisTest(const hitbox::Polygon& a, const hitbox::Polygon& b)
{
    std::vector<hitbox::Vec2> normals = edgeNormals(a);
    const std::vector<hitbox::Vec2> normalsOfB = edgeNormals(b);
    normals.insert(normals.end(), normalsOfB.begin(), normalsOfB.end());
    if (normals.empty())
        return SatResult{}; // nothing to test (empty polygons): apart
    std::vector<AxisShadows> axes;
    for (const hitbox::Vec2& axis : normals)
        axes.push_back({axis, projectOnto(a, axis), projectOnto(b, axis)});
    return chooseAxis(axes);
}
