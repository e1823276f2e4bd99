// ShapeTable.h - every shape an object can collide as, and the exact test for every pair.
//
// One row per shape kind (its bounds for the broadphase, its outline for the debug renderer)
// and one cell per pair of kinds (the test). World, Collision::getContact and
// DebugRenderer::objectShape all read this table, so a new shape is added here and nowhere
// else: docs/adding-a-shape.md walks through it.
//
// Why a 2-D array of function pointers and not a switch: a new kind then fills a row and a
// column of cells, the compiler needs no new case in three files, and a test can make a
// table with a toy kind in it without touching Hitbox's code.
#pragma once

#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Shapes.h"

#include <array>
#include <cstddef>
#include <cstdint>

namespace hitbox
{
class GameObject;

// The kinds Hitbox knows. A kind is a small number (an index into the table): a table may
// hold more kinds than these, up to maxShapeKinds (a test adds a toy one as kind 2).
enum class ShapeKind : std::uint8_t
{
    Box,   // the object's world collision box (GameObject::getCollisionBox)
    Circle // the object's bounding circle (GameObject::getBoundingCircle)
};
constexpr std::size_t maxShapeKinds = 8;

// One row of the table: what a kind is, as plain functions of the object.
struct ShapeKindRow
{
    const char* name = nullptr;                             // nullptr: the kind is not in the table
    Box (*bounds)(const GameObject& object) = nullptr;      // contains the shape (broadphase)
    Polygon (*outline)(const GameObject& object) = nullptr; // its edge, in world pixels
};

// The exact test of one pair. The normal points out of `second` towards `first` (Shapes.h);
// hit is true only when they share area (the edge rule: touching is not colliding).
using PairTest = Contact (*)(const GameObject& first, const GameObject& second);

class ShapeTable
{
public:
    // An empty table: no kinds, no tests.
    ShapeTable() = default;
    // Hitbox's table: Box and Circle, and the three tests between them. Built once, on the
    // first call, and never changed after (a const table, not shared state): the default of
    // every query that takes a table costs no building. Copy it to add a kind.
    [[nodiscard]] static const ShapeTable& standard();

    // Puts `row` in the table as `kind` (replacing what was there). A kind past
    // maxShapeKinds is refused with std::invalid_argument.
    void addKind(ShapeKind kind, ShapeKindRow row);
    // The test for `first` against `second`. One direction is enough: the other is the same
    // test with the two swapped and the normal turned round.
    void setTest(ShapeKind first, ShapeKind second, PairTest test);

    // Is `kind` in the table?
    [[nodiscard]] bool has(ShapeKind kind) const;
    // True when every pair of kinds in the table has a test (one way round or the other).
    [[nodiscard]] bool isComplete() const;
    // The exact test of two objects as the given kinds. A kind not in the table, or a pair
    // with no test, never collides (hit false).
    [[nodiscard]] Contact test(const GameObject& first, ShapeKind firstKind,
                               const GameObject& second, ShapeKind secondKind) const;
    // A box containing the object as `kind` (empty, {0,0,0,0}, for a kind not in the table).
    [[nodiscard]] Box bounds(const GameObject& object, ShapeKind kind) const;
    // The object's outline as `kind` (no points for a kind not in the table).
    [[nodiscard]] Polygon outline(const GameObject& object, ShapeKind kind) const;
    // The kind's name ("box", "circle"; "unknown" when not in the table).
    [[nodiscard]] const char* nameOf(ShapeKind kind) const;

private:
    std::array<ShapeKindRow, maxShapeKinds> rows{};
    std::array<std::array<PairTest, maxShapeKinds>, maxShapeKinds> tests{};
};

} // namespace hitbox
