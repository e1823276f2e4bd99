// ShapeTable: a toy shape added through the steps of docs/adding-a-shape.md (a diamond: the
// rhombus whose corners are the middles of the collision box's sides), then used by World,
// Collision::getContact and DebugRenderer::objectShape without changing any of them.
#include "hitbox/debug/DebugRenderer.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/objects/Collision.h"
#include "hitbox/objects/ExplainPair.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/objects/ShapeTable.h"
#include "hitbox/objects/World.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace
{

// Step 1: a kind number after Hitbox's own (Box 0, Circle 1).
const hitbox::ShapeKind diamondKind = static_cast<hitbox::ShapeKind>(2);

// Step 2: the shape as plain geometry, from the object.
hitbox::Polygon diamondOf(const hitbox::GameObject& object)
{
    const hitbox::Box box = hitbox::normalised(hitbox::toBox(object.getCollisionBox()));
    const hitbox::Vec2 middle = hitbox::centerOf(box);
    return {{{middle.x, box.top},
             {box.left + box.width, middle.y},
             {middle.x, box.top + box.height},
             {box.left, middle.y}}};
}

hitbox::Box diamondBounds(const hitbox::GameObject& object)
{
    return hitbox::normalised(hitbox::toBox(object.getCollisionBox()));
}

// Step 3: a test against every kind already in the table (and itself).
hitbox::Contact diamondVsDiamond(const hitbox::GameObject& first, const hitbox::GameObject& second)
{
    return hitbox::polygonVsPolygon(diamondOf(first), diamondOf(second));
}

hitbox::Contact diamondVsBox(const hitbox::GameObject& first, const hitbox::GameObject& second)
{
    return hitbox::polygonVsPolygon(diamondOf(first),
                                    hitbox::toPolygon(hitbox::toBox(second.getCollisionBox())));
}

hitbox::Contact circleVsDiamond(const hitbox::GameObject& first, const hitbox::GameObject& second)
{
    return hitbox::circleVsPolygon(first.getBoundingCircle(), diamondOf(second));
}

// Step 4: the row and the cells.
hitbox::ShapeTable tableWithDiamonds()
{
    hitbox::ShapeTable table = hitbox::ShapeTable::standard();
    table.addKind(diamondKind, {"diamond", diamondBounds, diamondOf});
    table.setTest(diamondKind, diamondKind, diamondVsDiamond);
    table.setTest(diamondKind, hitbox::ShapeKind::Box, diamondVsBox);
    table.setTest(hitbox::ShapeKind::Circle, diamondKind, circleVsDiamond);
    return table;
}

hitbox::GameObject square(float left, float top)
{
    hitbox::GameObject object;
    object.setSize({40.f, 40.f});
    object.setPosition({left, top});
    return object;
}

class Counter : public hitbox::GameObject
{
public:
    int hits = 0;
    void collisionResponse(hitbox::GameObject*) override { ++hits; }
};

} // namespace

TEST(ShapeTable, StandardTableHasBoxAndCircleAndEveryPair)
{
    const hitbox::ShapeTable table = hitbox::ShapeTable::standard();
    EXPECT_TRUE(table.has(hitbox::ShapeKind::Box));
    EXPECT_TRUE(table.has(hitbox::ShapeKind::Circle));
    EXPECT_FALSE(table.has(diamondKind));
    EXPECT_TRUE(table.isComplete());
    EXPECT_STREQ(table.nameOf(hitbox::ShapeKind::Circle), "circle");
}

// Collision::getContact's default argument: one table for every call, not one built per call
// (docs/performance.md measures the difference); a copy can still be extended.
TEST(ShapeTable, TheStandardTableIsBuiltOnceAndACopyCanGrow)
{
    EXPECT_EQ(&hitbox::ShapeTable::standard(), &hitbox::ShapeTable::standard());
    hitbox::ShapeTable copy = hitbox::ShapeTable::standard();
    copy.addKind(diamondKind, {"diamond", diamondBounds, diamondOf});
    EXPECT_TRUE(copy.has(diamondKind));
    EXPECT_FALSE(hitbox::ShapeTable::standard().has(diamondKind));
}

TEST(ShapeTable, OneDirectionServesBothWithTheNormalTurnedRound)
{
    hitbox::GameObject ball = square(0.f, 0.f);
    hitbox::GameObject wall = square(30.f, 0.f); // 10 px of overlap, the wall on the right
    const hitbox::ShapeTable table = hitbox::ShapeTable::standard();
    const hitbox::Contact circleFirst =
        table.test(ball, hitbox::ShapeKind::Circle, wall, hitbox::ShapeKind::Box);
    const hitbox::Contact boxFirst =
        table.test(wall, hitbox::ShapeKind::Box, ball, hitbox::ShapeKind::Circle);
    ASSERT_TRUE(circleFirst.hit);
    ASSERT_TRUE(boxFirst.hit);
    EXPECT_FLOAT_EQ(circleFirst.normal.x, -1.f); // out of the wall towards the ball
    EXPECT_FLOAT_EQ(boxFirst.normal.x, 1.f);     // out of the ball towards the wall
    EXPECT_FLOAT_EQ(circleFirst.depth, boxFirst.depth);
}

TEST(ShapeTable, AKindWithoutATestAgainstEveryOtherIsIncompleteAndWorldRefusesIt)
{
    hitbox::ShapeTable table = hitbox::ShapeTable::standard();
    table.addKind(diamondKind, {"diamond", diamondBounds, diamondOf});
    table.setTest(diamondKind, diamondKind, diamondVsDiamond);
    EXPECT_FALSE(table.isComplete()); // no diamond-box or diamond-circle test yet
    EXPECT_THROW(hitbox::World(hitbox::BroadphaseMethod::Grid, table), std::invalid_argument);
    EXPECT_THROW(table.setTest(static_cast<hitbox::ShapeKind>(3), diamondKind, diamondVsDiamond),
                 std::invalid_argument);
    EXPECT_THROW(table.addKind(static_cast<hitbox::ShapeKind>(hitbox::maxShapeKinds), {}),
                 std::invalid_argument);
}

TEST(ShapeTable, WorldRefusesAKindNotInItsTable)
{
    hitbox::World world;
    hitbox::GameObject object = square(0.f, 0.f);
    EXPECT_THROW(world.add(object, 1, 1, diamondKind), std::invalid_argument);
    EXPECT_EQ(world.size(), 0u);
}

TEST(ShapeTable, WorldUsesTheToyShape)
{
    // Corner to corner: the boxes share a 10 x 10 corner, the diamonds nothing.
    Counter a;
    a.setSize({40.f, 40.f});
    Counter b;
    b.setSize({40.f, 40.f});
    b.setPosition({30.f, 30.f});
    hitbox::World boxes;
    boxes.add(a);
    boxes.add(b);
    EXPECT_EQ(boxes.checkCollisions(), 1u);
    boxes.clear();

    hitbox::World diamonds(hitbox::BroadphaseMethod::Grid, tableWithDiamonds());
    diamonds.add(a, 1, 1, diamondKind);
    diamonds.add(b, 1, 1, diamondKind);
    EXPECT_EQ(diamonds.checkCollisions(), 0u);
    EXPECT_EQ(diamonds.getShape(a), diamondKind);
    // Side by side with 10 px of overlap: the diamonds' side corners meet inside both.
    b.setPosition({30.f, 0.f});
    EXPECT_EQ(diamonds.checkCollisions(), 1u);
    EXPECT_EQ(a.hits, 2); // one from the boxes, one from the diamonds
}

TEST(ShapeTable, WorldTestsTheToyShapeAgainstHitboxsOwnKinds)
{
    Counter diamond;
    diamond.setSize({40.f, 40.f});
    Counter box;
    box.setSize({40.f, 40.f});
    box.setPosition({30.f, 30.f}); // in the diamond's empty corner
    hitbox::World world(hitbox::BroadphaseMethod::SortAndSweep, tableWithDiamonds());
    world.add(diamond, 1, 1, diamondKind);
    world.add(box, 1, 1, hitbox::ShapeKind::Box);
    EXPECT_EQ(world.checkCollisions(), 0u);
    box.setPosition({10.f, 10.f}); // over the diamond's middle
    EXPECT_EQ(world.checkCollisions(), 1u);
    EXPECT_EQ(world.getCollisions().size(), 1u);
}

TEST(ShapeTable, CollisionGetContactUsesTheToyShape)
{
    hitbox::GameObject a = square(0.f, 0.f);
    hitbox::GameObject b = square(30.f, 30.f);
    const hitbox::ShapeTable table = tableWithDiamonds();
    EXPECT_TRUE(
        hitbox::Collision::getContact(&a, hitbox::ShapeKind::Box, &b, hitbox::ShapeKind::Box).hit);
    EXPECT_FALSE(hitbox::Collision::getContact(&a, diamondKind, &b, diamondKind, table).hit);
    b.setPosition({30.f, 0.f});
    const hitbox::Contact contact =
        hitbox::Collision::getContact(&a, diamondKind, &b, diamondKind, table);
    EXPECT_TRUE(contact.hit);
    EXPECT_LT(contact.normal.x, 0.f); // out of b (on the right) towards a
    // Collision's own rules still come first: an object against itself never collides.
    EXPECT_FALSE(hitbox::Collision::getContact(&a, diamondKind, &a, diamondKind, table).hit);
}

TEST(ShapeTable, ExplainGivesTheTablesAnswerForAKindItHasNoWordsFor)
{
    hitbox::GameObject a = square(0.f, 0.f);
    hitbox::GameObject b = square(30.f, 30.f); // the boxes overlap, the diamonds do not
    a.setName("a");
    b.setName("b");
    const hitbox::ShapeTable table = tableWithDiamonds();
    const hitbox::Explanation apart = hitbox::explain(a, b, diamondKind, diamondKind, table);
    EXPECT_FALSE(apart.collides);
    EXPECT_EQ(apart.verdict, "'a' and 'b' do not collide (the diamond-diamond test says so); no "
                             "explanation for shape kind 2 (only box and circle are explained)");
    b.setPosition({30.f, 0.f});
    const hitbox::Explanation meet =
        hitbox::explain(a, b, diamondKind, hitbox::ShapeKind::Box, table);
    EXPECT_TRUE(meet.collides);
    EXPECT_EQ(meet.verdict.rfind("'a' and 'b' collide (the diamond-box test says so)", 0), 0u)
        << meet.verdict;
}

TEST(ShapeTable, DebugRendererDrawsTheToyShapeFromItsOutline)
{
    hitbox::GameObject a = square(0.f, 0.f);
    const hitbox::ShapeTable table = tableWithDiamonds();
    hitbox::DebugRenderer asDiamond;
    asDiamond.objectShape(a, diamondKind, hitbox::DebugState::Free, table);
    // Four edges, two triangles (six vertices) each, then the velocity arrow: standing still,
    // a zero-length line (a 2-pixel dot at the middle).
    ASSERT_EQ(asDiamond.getVertices().getVertexCount(), 5u * 6u);
    // Every vertex of the outline within a line's width of the diamond, none near the box's
    // corners.
    for (std::size_t i = 0; i < 4u * 6u; ++i)
    {
        const sf::Vector2f p = asDiamond.getVertices()[i].position;
        const float fromMiddle = std::abs(p.x - 20.f) + std::abs(p.y - 20.f);
        EXPECT_NEAR(fromMiddle, 20.f, 2.f) << p.x << ", " << p.y;
    }
    hitbox::DebugRenderer hatched;
    hatched.objectShape(a, diamondKind, hitbox::DebugState::Overlapping, table);
    EXPECT_GT(hatched.getVertices().getVertexCount(), 5u * 6u); // outline, arrow, hatching
}

TEST(ShapeTable, DebugRendererDrawsPolygons)
{
    hitbox::DebugRenderer debug;
    debug.polygon(hitbox::toPolygon(hitbox::OrientedBox{{50.f, 50.f}, {20.f, 10.f}, 30.f}),
                  hitbox::DebugState::Free);
    EXPECT_EQ(debug.getVertices().getVertexCount(), 4u * 6u);
    hitbox::DebugRenderer nothing;
    nothing.polygon(hitbox::Polygon{{{1.f, 1.f}}}, hitbox::DebugState::Overlapping);
    EXPECT_EQ(nothing.getVertices().getVertexCount(), 0u); // one point: no edge to draw
}
