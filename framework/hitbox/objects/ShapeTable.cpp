#include "hitbox/objects/ShapeTable.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/objects/GameObject.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace hitbox
{
namespace
{

// A circle's outline: as many corners as DebugRenderer::circle draws arcs.
const int circleOutlineCorners = 32;

std::size_t indexOf(ShapeKind kind)
{
    return static_cast<std::size_t>(kind);
}

Box boxOf(const GameObject& object)
{
    return normalised(toBox(object.getCollisionBox()));
}

Box circleBounds(const GameObject& object)
{
    const Circle circle = object.getBoundingCircle();
    return {circle.center.x - circle.radius, circle.center.y - circle.radius, 2.f * circle.radius,
            2.f * circle.radius};
}

Polygon boxOutline(const GameObject& object)
{
    return toPolygon(boxOf(object));
}

Polygon circleOutline(const GameObject& object)
{
    const Circle circle = object.getBoundingCircle();
    Polygon outline;
    for (int i = 0; i < circleOutlineCorners; ++i)
    {
        const float angle = 2.f * pi * static_cast<float>(i) / circleOutlineCorners;
        outline.points.push_back(circle.center +
                                 Vec2(std::cos(angle), std::sin(angle)) * circle.radius);
    }
    return outline;
}

// A hit found by a bool test: the bool test decides (the edge rule lives there), the contact
// only describes the hit, so it is computed only then.
Contact hitDescribedBy(Contact contact)
{
    contact.hit = true;
    return contact;
}

Contact boxVsBoxTest(const GameObject& first, const GameObject& second)
{
    const Box a = toBox(first.getCollisionBox());
    const Box b = toBox(second.getCollisionBox());
    return boxVsBox(a, b) ? hitDescribedBy(boxVsBoxContact(a, b)) : Contact{};
}

Contact circleVsCircleTest(const GameObject& first, const GameObject& second)
{
    const Circle a = first.getBoundingCircle();
    const Circle b = second.getBoundingCircle();
    return circleVsCircle(a, b) ? hitDescribedBy(circleVsCircleContact(a, b)) : Contact{};
}

Contact circleVsBoxTest(const GameObject& first, const GameObject& second)
{
    const Circle a = first.getBoundingCircle();
    const Box b = toBox(second.getCollisionBox());
    return circleVsBox(a, b) ? hitDescribedBy(circleVsBoxContact(a, b)) : Contact{};
}

ShapeTable buildStandard()
{
    ShapeTable table;
    table.addKind(ShapeKind::Box, {"box", boxOf, boxOutline});
    table.addKind(ShapeKind::Circle, {"circle", circleBounds, circleOutline});
    table.setTest(ShapeKind::Box, ShapeKind::Box, boxVsBoxTest);
    table.setTest(ShapeKind::Circle, ShapeKind::Circle, circleVsCircleTest);
    table.setTest(ShapeKind::Circle, ShapeKind::Box, circleVsBoxTest);
    return table;
}

} // namespace

// Nothing to tear down at exit (so no order of destruction to get wrong), whatever reads it last.
static_assert(std::is_trivially_destructible_v<ShapeTable>,
              "the standard table outlives its users");

const ShapeTable& ShapeTable::standard()
{
    // A function-local static is built once, on first use, even with threads (C++17
    // [stmt.dcl]/4); const, so every caller sees the same three tests.
    static const ShapeTable table = buildStandard();
    return table;
}

void ShapeTable::addKind(ShapeKind kind, ShapeKindRow row)
{
    if (indexOf(kind) >= maxShapeKinds)
        throw std::invalid_argument("hitbox::ShapeTable: shape kind " +
                                    std::to_string(indexOf(kind)) + " is past maxShapeKinds (" +
                                    std::to_string(maxShapeKinds) + ")");
    rows[indexOf(kind)] = row;
}

void ShapeTable::setTest(ShapeKind first, ShapeKind second, PairTest test)
{
    if (!has(first) || !has(second))
        throw std::invalid_argument("hitbox::ShapeTable: add both shape kinds before their test");
    tests[indexOf(first)][indexOf(second)] = test;
}

bool ShapeTable::has(ShapeKind kind) const
{
    return indexOf(kind) < maxShapeKinds && rows[indexOf(kind)].name != nullptr;
}

bool ShapeTable::isComplete() const
{
    for (std::size_t a = 0; a < maxShapeKinds; ++a)
        for (std::size_t b = 0; b < maxShapeKinds; ++b)
            if (rows[a].name != nullptr && rows[b].name != nullptr && tests[a][b] == nullptr &&
                tests[b][a] == nullptr)
                return false;
    return true;
}

Contact ShapeTable::test(const GameObject& first, ShapeKind firstKind, const GameObject& second,
                         ShapeKind secondKind) const
{
    if (!has(firstKind) || !has(secondKind))
        return {};
    if (const PairTest forward = tests[indexOf(firstKind)][indexOf(secondKind)])
        return forward(first, second);
    if (const PairTest backward = tests[indexOf(secondKind)][indexOf(firstKind)])
    {
        Contact contact = backward(second, first);
        contact.normal = -contact.normal; // out of `second` towards `first` again
        return contact;
    }
    return {};
}

Box ShapeTable::bounds(const GameObject& object, ShapeKind kind) const
{
    return has(kind) ? rows[indexOf(kind)].bounds(object) : Box{};
}

Polygon ShapeTable::outline(const GameObject& object, ShapeKind kind) const
{
    return has(kind) ? rows[indexOf(kind)].outline(object) : Polygon{};
}

const char* ShapeTable::nameOf(ShapeKind kind) const
{
    return has(kind) ? rows[indexOf(kind)].name : "unknown";
}

} // namespace hitbox
