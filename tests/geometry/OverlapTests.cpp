// Overlap tests: the edge rule (touching is not colliding), degenerate inputs, symmetry,
// translation invariance, and agreement with independent references on random cases.
#include "support/Printers.h"

#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Vec2.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

#include <cmath>
#include <limits>
#include <random>

using hitbox::Circle;
using hitbox::Contact;

namespace
{
const float notANumber = std::numeric_limits<float>::quiet_NaN();
const float infinite = std::numeric_limits<float>::infinity();
} // namespace

// ---- Point in box ------------------------------------------------------------------------

TEST(PointInBox, InsideIsInside)
{
    EXPECT_TRUE(hitbox::pointInBox({5.f, 5.f}, {0.f, 0.f, 10.f, 10.f}));
}

TEST(PointInBox, OutsideIsOutside)
{
    EXPECT_FALSE(hitbox::pointInBox({15.f, 5.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::pointInBox({5.f, -1.f}, {0.f, 0.f, 10.f, 10.f}));
}

TEST(PointInBox, PointOnAnyEdgeOrCornerIsOutside)
{
    const hitbox::Box box{0.f, 0.f, 10.f, 10.f};
    EXPECT_FALSE(hitbox::pointInBox({0.f, 5.f}, box));
    EXPECT_FALSE(hitbox::pointInBox({10.f, 5.f}, box));
    EXPECT_FALSE(hitbox::pointInBox({5.f, 0.f}, box));
    EXPECT_FALSE(hitbox::pointInBox({5.f, 10.f}, box));
    EXPECT_FALSE(hitbox::pointInBox({10.f, 10.f}, box));
}

TEST(PointInBox, NegativeSizeBoxSpansBackwards)
{
    // Width -10 from x = 10 covers 0..10, as sf::Rect reads it.
    EXPECT_TRUE(hitbox::pointInBox({5.f, 5.f}, {10.f, 10.f, -10.f, -10.f}));
    EXPECT_FALSE(hitbox::pointInBox({15.f, 5.f}, {10.f, 10.f, -10.f, -10.f}));
}

TEST(PointInBox, ZeroSizeBoxContainsNothing)
{
    EXPECT_FALSE(hitbox::pointInBox({5.f, 5.f}, {5.f, 5.f, 0.f, 0.f}));
}

TEST(PointInBox, NanOrInfinityIsNeverInside)
{
    EXPECT_FALSE(hitbox::pointInBox({notANumber, 5.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::pointInBox({5.f, 5.f}, {0.f, 0.f, notANumber, 10.f}));
    EXPECT_FALSE(hitbox::pointInBox({5.f, 5.f}, {-infinite, 0.f, infinite, 10.f}));
}

// ---- Point in circle ---------------------------------------------------------------------

TEST(PointInCircle, InsideOutsideAndOnTheRim)
{
    const Circle circle{{0.f, 0.f}, 5.f};
    EXPECT_TRUE(hitbox::pointInCircle({3.f, 3.f}, circle));
    EXPECT_FALSE(hitbox::pointInCircle({4.f, 4.f}, circle));
    EXPECT_FALSE(hitbox::pointInCircle({3.f, 4.f}, circle)); // exactly on the rim: 3-4-5
}

TEST(PointInCircle, NegativeOrNanRadiusContainsNothing)
{
    EXPECT_FALSE(hitbox::pointInCircle({0.f, 0.f}, {{0.f, 0.f}, -5.f}));
    EXPECT_FALSE(hitbox::pointInCircle({0.f, 0.f}, {{0.f, 0.f}, notANumber}));
}

// ---- Box vs box --------------------------------------------------------------------------

TEST(BoxVsBox, OverlappingBoxesCollide)
{
    EXPECT_TRUE(hitbox::boxVsBox({0.f, 0.f, 10.f, 10.f}, {5.f, 5.f, 10.f, 10.f}));
}

TEST(BoxVsBox, SeparatedBoxesDoNot)
{
    EXPECT_FALSE(hitbox::boxVsBox({0.f, 0.f, 10.f, 10.f}, {20.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::boxVsBox({0.f, 0.f, 10.f, 10.f}, {0.f, 20.f, 10.f, 10.f}));
}

TEST(BoxVsBox, TouchingEdgesDoNotOverlap)
{
    const hitbox::Box box{0.f, 0.f, 10.f, 10.f};
    EXPECT_FALSE(hitbox::boxVsBox(box, {10.f, 0.f, 10.f, 10.f}));  // right edge
    EXPECT_FALSE(hitbox::boxVsBox(box, {-10.f, 0.f, 10.f, 10.f})); // left edge
    EXPECT_FALSE(hitbox::boxVsBox(box, {0.f, 10.f, 10.f, 10.f}));  // bottom edge
    EXPECT_FALSE(hitbox::boxVsBox(box, {10.f, 10.f, 10.f, 10.f})); // corner
}

TEST(BoxVsBox, TouchingEdgesDoNotOverlapAsInSfml)
{
    // The lecture's version counted touching as a hit; SFML does not; Hitbox follows SFML.
    const hitbox::Box a{0.f, 0.f, 10.f, 10.f};
    const hitbox::Box b{10.f, 0.f, 10.f, 10.f};
    EXPECT_FALSE(hitbox::boxVsBox(a, b));
}

TEST(BoxVsBox, BoxInsideAnotherCollides)
{
    EXPECT_TRUE(hitbox::boxVsBox({2.f, 2.f, 1.f, 1.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_TRUE(hitbox::boxVsBox({0.f, 0.f, 10.f, 10.f}, {2.f, 2.f, 1.f, 1.f}));
}

TEST(BoxVsBox, ZeroSizeBoxIsAPointThatCollidesOnlyStrictlyInside)
{
    EXPECT_TRUE(hitbox::boxVsBox({5.f, 5.f, 0.f, 0.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::boxVsBox({10.f, 5.f, 0.f, 0.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::boxVsBox({5.f, 5.f, 0.f, 0.f}, {5.f, 5.f, 0.f, 0.f}));
}

TEST(BoxVsBox, NegativeSizesAreReadLikeSfml)
{
    const hitbox::Box flipped{10.f, 10.f, -10.f, -10.f}; // the box 0..10 x 0..10
    EXPECT_TRUE(hitbox::boxVsBox(flipped, {5.f, 5.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::boxVsBox(flipped, {10.f, 0.f, 10.f, 10.f}));
}

TEST(BoxVsBox, AFlippedBoxTouchingAnotherStillOnlyTouches)
{
    // Flipping a negative width once moved the edge by a rounding error, so this pair
    // "overlapped" by 0.0000076 px while SFML said they only touch.
    const hitbox::Box flipped(-75.5923538f, 0.f, -30.5037346f, 10.f);
    const hitbox::Box after(-75.5923538f, 0.f, 5.f, 10.f);
    EXPECT_FALSE(hitbox::boxVsBox(flipped, after));
    EXPECT_EQ(hitbox::rightOf(hitbox::normalised(flipped)), flipped.left);

    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-1000.f, 1000.f), size(0.01f, 300.f);
    int disagreements = 0;
    for (int sample = 0; sample < 100000; ++sample)
    {
        const float edge = coordinate(random);
        const hitbox::Box first(edge, 0.f, -size(random), 10.f); // ends at `edge`
        const hitbox::Box second(edge, 0.f, size(random), 10.f); // starts there
        disagreements += hitbox::boxVsBox(first, second);
    }
    EXPECT_EQ(disagreements, 0);
}

TEST(BoxVsBox, NanOrInfinityNeverCollides)
{
    EXPECT_FALSE(hitbox::boxVsBox({notANumber, 0.f, 10.f, 10.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::boxVsBox({0.f, 0.f, 10.f, 10.f}, {0.f, 0.f, 10.f, notANumber}));
    EXPECT_FALSE(hitbox::boxVsBox({0.f, 0.f, infinite, 10.f}, {0.f, 0.f, 10.f, 10.f}));
}

TEST(BoxVsBoxContact, PushesAlongTheShallowerAxis)
{
    // A overlaps B's left side by 2 px and its top by 8 px: push A left by 2.
    const Contact contact =
        hitbox::boxVsBoxContact({-8.f, -2.f, 10.f, 10.f}, {0.f, 0.f, 10.f, 10.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 2.f);
    EXPECT_FLOAT_EQ(contact.point.x, 0.f);
}

TEST(BoxVsBoxContact, DepthIsTheMinimumTranslationEvenWhenContained)
{
    // A small box near B's right edge leaves through the right, not by its own width.
    const Contact contact = hitbox::boxVsBoxContact({8.f, 4.f, 1.f, 2.f}, {0.f, 0.f, 10.f, 10.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 2.f);
}

TEST(BoxVsBoxContact, SameCentrePushesTowardsMinusX)
{
    const Contact contact = hitbox::boxVsBoxContact({0.f, 0.f, 10.f, 10.f}, {0.f, 0.f, 10.f, 10.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 10.f);
}

TEST(BoxVsBoxContact, TouchingGivesNoContact)
{
    EXPECT_FALSE(hitbox::boxVsBoxContact({0.f, 0.f, 10.f, 10.f}, {10.f, 0.f, 10.f, 10.f}).hit);
}

// ---- Circle vs circle --------------------------------------------------------------------

TEST(CircleVsCircle, OverlapAndSeparation)
{
    EXPECT_TRUE(hitbox::circleVsCircle({{0.f, 0.f}, 5.f}, {{8.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, 5.f}, {{11.f, 0.f}, 5.f}));
}

TEST(CircleVsCircle, TouchingCirclesDoNotCollide)
{
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, 5.f}, {{10.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, 2.f}, {{6.f, 8.f}, 8.f})); // 6-8-10
}

TEST(CircleVsCircle, ZeroRadiusIsAPoint)
{
    EXPECT_TRUE(hitbox::circleVsCircle({{1.f, 0.f}, 0.f}, {{0.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, 0.f}, {{0.f, 0.f}, 0.f}));
}

TEST(CircleVsCircle, NegativeRadiusOrNanNeverCollides)
{
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, -1.f}, {{0.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::circleVsCircle({{notANumber, 0.f}, 1.f}, {{0.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::circleVsCircle({{0.f, 0.f}, infinite}, {{0.f, 0.f}, 5.f}));
}

TEST(CircleVsCircleContact, NormalDepthAndPoint)
{
    const Contact contact = hitbox::circleVsCircleContact({{8.f, 0.f}, 5.f}, {{0.f, 0.f}, 5.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 2.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(5.f, 0.f));
}

TEST(CircleVsCircleContact, SameCentrePushesTowardsMinusX)
{
    const Contact contact = hitbox::circleVsCircleContact({{3.f, 3.f}, 2.f}, {{3.f, 3.f}, 5.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 7.f);
}

TEST(CircleVsCircleContact, EveryHitHasADepthAboveZeroEvenWhenNearlyTouching)
{
    // The yes/no test and the depth round differently; a hit must never say "depth 0".
    const Contact example = hitbox::circleVsCircleContact(
        {{45.182251f, 950.279297f}, 48.755249f}, {{33.8508224f, 1024.47742f}, 26.3031464f});
    EXPECT_TRUE(!example.hit || example.depth > 0.f) << "depth " << example.depth;
    std::mt19937 random(99);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    int hits = 0;
    int hitsWithoutDepth = 0;
    for (int sample = 0; sample < 100000; ++sample)
    {
        const Circle a{{2000.f * unit(random) - 1000.f, 2000.f * unit(random) - 1000.f},
                       100.f * unit(random)};
        const float angle = 2.f * hitbox::pi * unit(random);
        const float distance = a.radius + 100.f * unit(random);
        const Circle b{
            {a.center.x + distance * std::cos(angle), a.center.y + distance * std::sin(angle)},
            distance - a.radius}; // touching, give or take rounding
        const Contact contact = hitbox::circleVsCircleContact(a, b);
        hits += contact.hit;
        hitsWithoutDepth += contact.hit && !(contact.depth > 0.f);
    }
    EXPECT_GT(hits, 0); // rounding does put some of them just inside
    EXPECT_EQ(hitsWithoutDepth, 0);
}

// ---- Circle vs box -----------------------------------------------------------------------

TEST(CircleVsBox, NearAFaceAndNearACorner)
{
    const hitbox::Box box{0.f, 0.f, 10.f, 10.f};
    EXPECT_TRUE(hitbox::circleVsBox({{12.f, 5.f}, 3.f}, box));
    EXPECT_FALSE(hitbox::circleVsBox({{14.f, 5.f}, 3.f}, box));
    // Near the corner (10, 10): distance to it is 5 * sqrt(2) ~ 7.07.
    EXPECT_TRUE(hitbox::circleVsBox({{15.f, 15.f}, 7.1f}, box));
    EXPECT_FALSE(hitbox::circleVsBox({{15.f, 15.f}, 7.f}, box));
}

TEST(CircleVsBox, TouchingAFaceOrACornerIsNotACollision)
{
    const hitbox::Box box{0.f, 0.f, 10.f, 10.f};
    EXPECT_FALSE(hitbox::circleVsBox({{13.f, 5.f}, 3.f}, box));
    EXPECT_FALSE(hitbox::circleVsBox({{13.f, 14.f}, 5.f}, box)); // corner (10,10), 3-4-5
}

TEST(CircleVsBox, CentreInsideCollidesEvenWithZeroRadius)
{
    EXPECT_TRUE(hitbox::circleVsBox({{5.f, 5.f}, 0.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::circleVsBox({{10.f, 5.f}, 0.f}, {0.f, 0.f, 10.f, 10.f}));
}

TEST(CircleVsBox, DegenerateInputs)
{
    EXPECT_FALSE(hitbox::circleVsBox({{5.f, 5.f}, -1.f}, {0.f, 0.f, 10.f, 10.f}));
    EXPECT_FALSE(hitbox::circleVsBox({{5.f, 5.f}, 1.f}, {0.f, notANumber, 10.f, 10.f}));
    EXPECT_TRUE(hitbox::circleVsBox({{5.f, 5.f}, 1.f}, {5.f, 5.f, 0.f, 0.f})); // box is a point
    EXPECT_TRUE(hitbox::circleVsBox({{5.f, 5.f}, 1.f}, {10.f, 10.f, -10.f, -10.f}));
}

TEST(CircleVsBoxContact, OutsideCentrePushesAwayFromTheNearestBoxPoint)
{
    const Contact contact = hitbox::circleVsBoxContact({{12.f, 5.f}, 3.f}, {0.f, 0.f, 10.f, 10.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 1.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(10.f, 5.f));
}

TEST(CircleVsBoxContact, InsideCentreLeavesThroughTheNearestEdge)
{
    const Contact contact = hitbox::circleVsBoxContact({{5.f, 9.f}, 2.f}, {0.f, 0.f, 10.f, 10.f});
    ASSERT_TRUE(contact.hit);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, 1.f));
    EXPECT_FLOAT_EQ(contact.depth, 3.f); // 1 px to the edge + the 2 px radius
    EXPECT_EQ(contact.point, hitbox::Vec2(5.f, 10.f));
}

// ---- Properties on random cases ----------------------------------------------------------

namespace
{

struct RandomShapes
{
    std::mt19937 random{20261122u};

    // Whole and half pixels make exact touching common, which is where bugs hide.
    float coordinate(float range)
    {
        return std::uniform_int_distribution<int>(static_cast<int>(-2 * range),
                                                  static_cast<int>(2 * range))(random) /
               2.f;
    }
    hitbox::Box box()
    {
        return {coordinate(50.f), coordinate(50.f), coordinate(20.f), coordinate(20.f)};
    }
    Circle circle() { return {{coordinate(50.f), coordinate(50.f)}, std::fabs(coordinate(20.f))}; }
    hitbox::Vec2 offset() { return {coordinate(1000.f), coordinate(1000.f)}; }
};

// Reference for circles: double precision, with the square root the fast test avoids.
bool circlesOverlapReference(const Circle& a, const Circle& b)
{
    const double dx = double(a.center.x) - b.center.x;
    const double dy = double(a.center.y) - b.center.y;
    return std::sqrt(dx * dx + dy * dy) < double(a.radius) + b.radius;
}

// Reference for circle vs box: the signed-distance formula for a box centred at the origin.
bool circleBoxReference(const Circle& c, const hitbox::Box& rawBox)
{
    const hitbox::Box box = hitbox::normalised(rawBox);
    const double halfWidth = box.width / 2.0;
    const double halfHeight = box.height / 2.0;
    const double dx = std::fabs(double(c.center.x) - (box.left + halfWidth)) - halfWidth;
    const double dy = std::fabs(double(c.center.y) - (box.top + halfHeight)) - halfHeight;
    const double outside = std::hypot(std::fmax(dx, 0.0), std::fmax(dy, 0.0));
    const double inside = std::fmin(std::fmax(dx, dy), 0.0);
    const double signedDistance = outside + inside;
    return signedDistance < c.radius || (inside < 0.0);
}

hitbox::Box moved(hitbox::Box box, hitbox::Vec2 by)
{
    box.left += by.x;
    box.top += by.y;
    return box;
}

} // namespace

TEST(OverlapProperties, BoxVsBoxAgreesWithDoublesAndIsSymmetricAndTranslationInvariant)
{
    RandomShapes shapes;
    for (int i = 0; i < 100000; ++i)
    {
        const hitbox::Box a = shapes.box();
        const hitbox::Box b = shapes.box();
        const bool overlap = hitbox::boxVsBox(a, b);
        // The same question in double precision, read straight from the fields (a negative
        // size spans backwards): strictly inside on both axes.
        const auto span = [](float start, float size)
        {
            const double end = double(start) + double(size);
            return std::make_pair(std::min(double(start), end), std::max(double(start), end));
        };
        const auto xOfA = span(a.left, a.width), yOfA = span(a.top, a.height);
        const auto xOfB = span(b.left, b.width), yOfB = span(b.top, b.height);
        const bool hasArea = a.width != 0.f && a.height != 0.f && b.width != 0.f && b.height != 0.f;
        if (hasArea)
        {
            const bool expected = xOfA.first < xOfB.second && xOfB.first < xOfA.second &&
                                  yOfA.first < yOfB.second && yOfB.first < yOfA.second;
            ASSERT_EQ(overlap, expected)
                << ::testing::PrintToString(a) << " " << ::testing::PrintToString(b);
        }
        ASSERT_EQ(overlap, hitbox::boxVsBox(b, a));
        const hitbox::Vec2 by = shapes.offset();
        ASSERT_EQ(overlap, hitbox::boxVsBox(moved(a, by), moved(b, by)));
        ASSERT_EQ(overlap, hitbox::boxVsBoxContact(a, b).hit);
    }
}

TEST(OverlapProperties, CircleVsCircleAgreesWithTheSquareRootVersion)
{
    RandomShapes shapes;
    for (int i = 0; i < 100000; ++i)
    {
        const Circle a = shapes.circle();
        const Circle b = shapes.circle();
        const bool overlap = hitbox::circleVsCircle(a, b);
        ASSERT_EQ(overlap, circlesOverlapReference(a, b))
            << ::testing::PrintToString(a) << " " << ::testing::PrintToString(b);
        ASSERT_EQ(overlap, hitbox::circleVsCircle(b, a));
        ASSERT_EQ(overlap, hitbox::circleVsCircleContact(a, b).hit);
    }
}

TEST(OverlapProperties, CircleVsBoxAgreesWithSignedDistance)
{
    RandomShapes shapes;
    for (int i = 0; i < 100000; ++i)
    {
        const Circle circle = shapes.circle();
        const hitbox::Box box = shapes.box();
        const bool overlap = hitbox::circleVsBox(circle, box);
        ASSERT_EQ(overlap, circleBoxReference(circle, box))
            << ::testing::PrintToString(circle) << " " << ::testing::PrintToString(box);
        ASSERT_EQ(overlap, hitbox::circleVsBoxContact(circle, box).hit);
    }
}

TEST(OverlapProperties, MovingByTheContactSeparatesAndNoLessWould)
{
    // The contact is a minimum translation: moving A by normal * depth leaves the shapes
    // touching (not colliding); moving by 99% of it leaves them colliding.
    RandomShapes shapes;
    int checked = 0;
    for (int i = 0; i < 50000; ++i)
    {
        const hitbox::Box a = shapes.box();
        const hitbox::Box b = shapes.box();
        const Contact boxes = hitbox::boxVsBoxContact(a, b);
        if (boxes.hit)
        {
            ++checked;
            EXPECT_FALSE(hitbox::boxVsBox(moved(a, boxes.normal * boxes.depth), b));
            EXPECT_TRUE(hitbox::boxVsBox(moved(a, boxes.normal * boxes.depth * 0.99f), b));
            // No other axis direction would separate with a shorter move.
            for (hitbox::Vec2 direction :
                 {hitbox::Vec2(1, 0), hitbox::Vec2(-1, 0), hitbox::Vec2(0, 1), hitbox::Vec2(0, -1)})
                EXPECT_TRUE(hitbox::boxVsBox(moved(a, direction * boxes.depth * 0.99f), b));
        }
        const Circle c1 = shapes.circle();
        const Circle c2 = shapes.circle();
        const Contact circles = hitbox::circleVsCircleContact(c1, c2);
        if (circles.hit && circles.depth > 0.01f)
        {
            Circle pushed = c1;
            pushed.center += circles.normal * (circles.depth + 1e-3f);
            EXPECT_FALSE(hitbox::circleVsCircle(pushed, c2));
            EXPECT_NEAR(std::hypot(circles.normal.x, circles.normal.y), 1.f, 1e-5f);
        }
        const Contact circleBox = hitbox::circleVsBoxContact(c1, b);
        if (circleBox.hit && circleBox.depth > 0.01f)
        {
            Circle pushed = c1;
            pushed.center += circleBox.normal * (circleBox.depth + 1e-3f);
            EXPECT_FALSE(hitbox::circleVsBox(pushed, b));
        }
    }
    EXPECT_GT(checked, 1000); // the random scenes really do overlap often enough
}

// The one inscribed circle (every GameObject's default bounding circle, the 2025 course's too):
// centred on the box, radius half the shorter side, a negative size read as its length.
TEST(InscribedCircle, CentredWithHalfTheShorterSide)
{
    const hitbox::Circle circle = hitbox::inscribedCircle({10.f, 20.f, 40.f, 30.f});
    EXPECT_FLOAT_EQ(circle.center.x, 30.f);
    EXPECT_FLOAT_EQ(circle.center.y, 35.f);
    EXPECT_FLOAT_EQ(circle.radius, 15.f);
    const hitbox::Circle flipped = hitbox::inscribedCircle({50.f, 50.f, -40.f, -30.f});
    EXPECT_FLOAT_EQ(flipped.center.x, 30.f); // the box spans 10..50 by 20..50
    EXPECT_FLOAT_EQ(flipped.center.y, 35.f);
    EXPECT_FLOAT_EQ(flipped.radius, 15.f);
    EXPECT_FLOAT_EQ(hitbox::inscribedCircle({0.f, 0.f, 0.f, 8.f}).radius, 0.f); // a point
}
