// PolygonTest.cpp - oriented boxes and convex polygons by the separating axis theorem
// (Polygon.h): the edge rules one test each. Random agreement is in AgreementTest.cpp.
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Overlap.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using hitbox::AxisReport;
using hitbox::Circle;
using hitbox::Contact;
using hitbox::OrientedBox;
using hitbox::Polygon;
using hitbox::polygonVsPolygon;
using hitbox::toPolygon;

namespace
{
const float notANumber = std::numeric_limits<float>::quiet_NaN();
const Polygon ground = toPolygon(hitbox::Box(0.f, 100.f, 200.f, 50.f)); // x 0..200, y 100..150

void expectNear(hitbox::Vec2 actual, hitbox::Vec2 expected, float tolerance = 1e-4f)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance) << ::testing::PrintToString(actual);
    EXPECT_NEAR(actual.y, expected.y, tolerance) << ::testing::PrintToString(actual);
}

Polygon reversed(Polygon polygon)
{
    std::reverse(polygon.points.begin(), polygon.points.end());
    return polygon;
}

Polygon diamond(hitbox::Vec2 centre, float halfDiagonal)
{
    return Polygon{
        {centre + hitbox::Vec2(0.f, -halfDiagonal), centre + hitbox::Vec2(halfDiagonal, 0.f),
         centre + hitbox::Vec2(0.f, halfDiagonal), centre + hitbox::Vec2(-halfDiagonal, 0.f)}};
}
} // namespace

// ---- making polygons ---------------------------------------------------------------------

TEST(ToPolygon, ABoxListsItsCornersDownTheLeftSideFirst)
{
    const Polygon box = toPolygon(hitbox::Box(10.f, 20.f, 30.f, 40.f));
    ASSERT_EQ(box.points.size(), 4u);
    EXPECT_EQ(box.points[0], hitbox::Vec2(10.f, 20.f));
    EXPECT_EQ(box.points[1], hitbox::Vec2(10.f, 60.f));
    EXPECT_EQ(box.points[2], hitbox::Vec2(40.f, 60.f));
    EXPECT_EQ(box.points[3], hitbox::Vec2(40.f, 20.f));
    // Negative sizes: the same box.
    EXPECT_EQ(toPolygon(hitbox::Box(40.f, 60.f, -30.f, -40.f)).points, box.points);
}

TEST(ToPolygon, AnUnturnedOrientedBoxIsTheAxisAlignedBox)
{
    const Polygon turned = toPolygon(OrientedBox{{25.f, 40.f}, {15.f, 20.f}, 0.f});
    EXPECT_EQ(turned.points, toPolygon(hitbox::Box(10.f, 20.f, 30.f, 40.f)).points);
}

TEST(ToPolygon, QuarterTurnsAreExact)
{
    // Turned 90 degrees (clockwise on screen), a 30 x 40 box covers 40 x 30.
    const Polygon turned = toPolygon(OrientedBox{{0.f, 0.f}, {15.f, 20.f}, 90.f});
    for (hitbox::Vec2 corner : turned.points)
    {
        EXPECT_EQ(std::fabs(corner.x), 20.f);
        EXPECT_EQ(std::fabs(corner.y), 15.f);
    }
    EXPECT_EQ(toPolygon(OrientedBox{{0.f, 0.f}, {15.f, 20.f}, -270.f}).points, turned.points);
}

TEST(ToPolygon, TurnsClockwiseOnScreenLikeSfml)
{
    // SFML turns (1, 0) by +90 degrees to (0, 1): down the screen.
    const Polygon turned = toPolygon(OrientedBox{{0.f, 0.f}, {10.f, 0.f}, 30.f});
    // The first corner is the box's own (-10, 0); turned 30 degrees it goes up-left.
    expectNear(turned.points[0], {-10.f * std::cos(0.5236f), -10.f * std::sin(0.5236f)}, 1e-3f);
}

// ---- SAT: polygon vs polygon -------------------------------------------------------------

TEST(PolygonVsPolygon, OverlappingBoxesGiveTheMinimumTranslation)
{
    const Polygon crate = toPolygon(hitbox::Box(50.f, 60.f, 40.f, 45.f)); // 5 px into the floor
    const Contact contact = polygonVsPolygon(crate, ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f)); // out of the floor, towards the crate
    EXPECT_FLOAT_EQ(contact.depth, 5.f);
    EXPECT_FLOAT_EQ(contact.point.y, 100.f); // on the floor's surface
}

TEST(PolygonVsPolygon, AgreesWithBoxVsBoxContactOnAxisAlignedBoxes)
{
    // Same normals and depths, ties included (x first, then left/up), on whole-number boxes
    // where ties are common.
    std::mt19937 random(3u);
    std::uniform_int_distribution<int> coordinate(0, 12);
    std::uniform_int_distribution<int> size(0, 8);
    int hits = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const hitbox::Box a(float(coordinate(random)), float(coordinate(random)),
                            float(size(random)), float(size(random)));
        const hitbox::Box b(float(coordinate(random)), float(coordinate(random)),
                            float(size(random)), float(size(random)));
        const bool bothFlat =
            (a.width == 0.f || a.height == 0.f) && (b.width == 0.f || b.height == 0.f);
        if (bothFlat)
            continue; // boxVsBox lets two crossing lines collide; polygons with no area never do
        const Contact boxes = hitbox::boxVsBoxContact(a, b);
        const Contact polygons = polygonVsPolygon(toPolygon(a), toPolygon(b));
        ASSERT_EQ(boxes.hit, polygons.hit)
            << ::testing::PrintToString(a) << " " << ::testing::PrintToString(b);
        if (!boxes.hit)
            continue;
        ++hits;
        EXPECT_EQ(boxes.normal, polygons.normal)
            << ::testing::PrintToString(a) << " " << ::testing::PrintToString(b);
        EXPECT_EQ(boxes.depth, polygons.depth);
    }
    EXPECT_GT(hits, 1000);
}

TEST(PolygonVsPolygon, TouchingEdgesDoNotCollide)
{
    EXPECT_FALSE(polygonVsPolygon(toPolygon(hitbox::Box(50.f, 60.f, 40.f, 40.f)), ground));
    EXPECT_FALSE(polygonVsPolygon(toPolygon(hitbox::Box(200.f, 100.f, 10.f, 10.f)), ground));
}

TEST(PolygonVsPolygon, ACornerTouchingAnEdgeDoesNotCollide)
{
    // A diamond standing on its tip exactly on the floor.
    EXPECT_FALSE(polygonVsPolygon(diamond({100.f, 90.f}, 10.f), ground));
    // 2 px lower it is 2 px in, and the shortest way out is straight up.
    const Contact contact = polygonVsPolygon(diamond({100.f, 92.f}, 10.f), ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(contact.depth, 2.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(100.f, 100.f));
}

TEST(PolygonVsPolygon, RotatedBoxesWhoseBoundingBoxesOverlapCanBeApart)
{
    // Two diamonds side by side: their bounding boxes overlap, the diamonds do not.
    const Polygon left = diamond({0.f, 0.f}, 10.f);
    const Polygon right = diamond({15.f, 10.f}, 10.f);
    EXPECT_TRUE(hitbox::boxVsBox({-10.f, -10.f, 20.f, 20.f}, {5.f, 0.f, 20.f, 20.f}));
    EXPECT_FALSE(polygonVsPolygon(left, right));
}

TEST(PolygonVsPolygon, EitherWindingGivesTheSameAnswer)
{
    const Polygon crate = toPolygon(OrientedBox{{100.f, 95.f}, {20.f, 10.f}, 30.f});
    const Contact forward = polygonVsPolygon(crate, ground);
    const Contact backward = polygonVsPolygon(reversed(crate), reversed(ground));
    ASSERT_TRUE(forward);
    ASSERT_TRUE(backward);
    EXPECT_EQ(forward.normal, backward.normal);
    EXPECT_FLOAT_EQ(forward.depth, backward.depth);
}

TEST(PolygonVsPolygon, SwappingTheShapesReversesTheNormal)
{
    const Polygon crate = toPolygon(OrientedBox{{100.f, 95.f}, {20.f, 10.f}, 30.f});
    const Contact ab = polygonVsPolygon(crate, ground);
    const Contact ba = polygonVsPolygon(ground, crate);
    ASSERT_TRUE(ab);
    ASSERT_TRUE(ba);
    expectNear(ab.normal, -ba.normal);
    EXPECT_FLOAT_EQ(ab.depth, ba.depth);
}

TEST(PolygonVsPolygon, APolygonInsideAnotherLeavesTheShortWay)
{
    // A small box inside the floor, 3 px from its left side.
    const Contact contact = polygonVsPolygon(toPolygon(hitbox::Box(3.f, 110.f, 5.f, 5.f)), ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 8.f); // its right side must clear x = 0
}

TEST(PolygonVsPolygon, MovingByTheContactLeavesThemTouching)
{
    Polygon crate = toPolygon(OrientedBox{{60.f, 97.f}, {25.f, 8.f}, 20.f});
    const Contact contact = polygonVsPolygon(crate, ground);
    ASSERT_TRUE(contact);
    for (hitbox::Vec2& p : crate.points)
        p += contact.normal * (contact.depth * 0.99f);
    EXPECT_TRUE(polygonVsPolygon(crate, ground)); // 1% short: still in
    for (hitbox::Vec2& p : crate.points)
        p += contact.normal * (contact.depth * 0.02f);
    EXPECT_FALSE(polygonVsPolygon(crate, ground)); // 1% past: out
}

TEST(PolygonVsPolygon, APointCollidesOnlyStrictlyInside)
{
    EXPECT_TRUE(polygonVsPolygon(Polygon{{{10.f, 110.f}}}, ground));
    EXPECT_FALSE(polygonVsPolygon(Polygon{{{10.f, 100.f}}}, ground)); // on the edge
    EXPECT_FALSE(polygonVsPolygon(Polygon{{{0.f, 100.f}}}, ground));  // on the corner
    const Contact contact = polygonVsPolygon(Polygon{{{10.f, 102.f}}}, ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(contact.depth, 2.f);
}

TEST(PolygonVsPolygon, ASegmentCollidesWhenItReachesInside)
{
    EXPECT_TRUE(polygonVsPolygon(Polygon{{{-10.f, 120.f}, {10.f, 120.f}}}, ground));
    EXPECT_FALSE(
        polygonVsPolygon(Polygon{{{-10.f, 100.f}, {300.f, 100.f}}}, ground)); // along the edge
    EXPECT_FALSE(polygonVsPolygon(Polygon{{{-10.f, 120.f}, {0.f, 120.f}}}, ground)); // ends on it
}

TEST(PolygonVsPolygon, ShapesWithNoAreaNeverCollideWithEachOther)
{
    const Polygon across{{{0.f, 0.f}, {10.f, 10.f}}};
    const Polygon down{{{0.f, 10.f}, {10.f, 0.f}}};
    EXPECT_FALSE(polygonVsPolygon(across, down)); // crossing segments
    EXPECT_FALSE(polygonVsPolygon(Polygon{{{5.f, 5.f}}}, across));
    EXPECT_FALSE(polygonVsPolygon(toPolygon(hitbox::Box(0.f, 5.f, 10.f, 0.f)),
                                  toPolygon(hitbox::Box(5.f, 0.f, 0.f, 10.f))));
}

TEST(PolygonVsPolygon, RepeatedPointsAreIgnored)
{
    const Polygon crate = toPolygon(hitbox::Box(50.f, 60.f, 40.f, 45.f));
    Polygon stuttering;
    for (hitbox::Vec2 p : crate.points)
    {
        stuttering.points.push_back(p);
        stuttering.points.push_back(p);
    }
    stuttering.points.push_back(crate.points[0]); // closed by repeating the first point
    const Contact contact = polygonVsPolygon(stuttering, ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(contact.depth, 5.f);
}

TEST(PolygonVsPolygon, EmptyOrNaNNeverCollides)
{
    EXPECT_FALSE(polygonVsPolygon(Polygon{}, ground));
    EXPECT_FALSE(
        polygonVsPolygon(Polygon{{{notANumber, 110.f}, {10.f, 120.f}, {20.f, 110.f}}}, ground));
    EXPECT_FALSE(
        hitbox::orientedBoxVsOrientedBox(OrientedBox{{10.f, 110.f}, {5.f, 5.f}, notANumber},
                                         OrientedBox{{10.f, 110.f}, {5.f, 5.f}, 0.f}));
}

TEST(OrientedBoxVsOrientedBox, TurningABoxCanMakeItCollide)
{
    // A plank lying level just below a crate (2 px gap), then turned 30 degrees: its left
    // end swings up (clockwise on screen) into the crate.
    const OrientedBox crate{{0.f, 0.f}, {10.f, 10.f}, 0.f}; // y -10..10
    OrientedBox plank{{20.f, 14.f}, {20.f, 2.f}, 0.f};      // y 12..16
    EXPECT_FALSE(hitbox::orientedBoxVsOrientedBox(plank, crate));
    plank.angleDegrees = 30.f;
    EXPECT_TRUE(hitbox::orientedBoxVsOrientedBox(plank, crate));
}

// ---- the separating axis, for drawing ----------------------------------------------------

TEST(FindSeparatingAxis, ApartGivesTheWidestGapPointingTowardsA)
{
    const Polygon right =
        toPolygon(hitbox::Box(210.f, 100.f, 20.f, 20.f)); // 10 px right of the floor
    const AxisReport report = hitbox::findSeparatingAxis(right, ground);
    EXPECT_TRUE(report.separated);
    EXPECT_EQ(report.axis, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(report.gap, 10.f);
    const AxisReport swapped = hitbox::findSeparatingAxis(ground, right);
    EXPECT_EQ(swapped.axis, hitbox::Vec2(-1.f, 0.f));
}

TEST(FindSeparatingAxis, TouchingIsSeparatedWithAZeroGap)
{
    const AxisReport report =
        hitbox::findSeparatingAxis(toPolygon(hitbox::Box(50.f, 60.f, 40.f, 40.f)), ground);
    EXPECT_TRUE(report.separated);
    EXPECT_EQ(report.gap, 0.f);
    EXPECT_EQ(report.axis, hitbox::Vec2(0.f, -1.f));
}

TEST(FindSeparatingAxis, OverlappingGivesTheLeastOverlapAsANegativeGap)
{
    const Polygon crate = toPolygon(hitbox::Box(50.f, 60.f, 40.f, 45.f));
    const AxisReport report = hitbox::findSeparatingAxis(crate, ground);
    EXPECT_FALSE(report.separated);
    EXPECT_EQ(report.axis, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(report.gap, -5.f);
}

TEST(FindSeparatingAxis, NothingToTestGivesNoAxis)
{
    const AxisReport report = hitbox::findSeparatingAxis(Polygon{}, ground);
    EXPECT_TRUE(report.separated);
    EXPECT_EQ(report.axis, hitbox::Vec2(0.f, 0.f));
    EXPECT_EQ(report.gap, 0.f);
}

// ---- polygon vs circle -------------------------------------------------------------------

TEST(CircleVsPolygon, NearAnEdgePushesStraightOut)
{
    const Contact contact = hitbox::circleVsPolygon(Circle{{50.f, 95.f}, 10.f}, ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(contact.depth, 5.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(50.f, 100.f));
}

TEST(CircleVsPolygon, NearACornerPushesAwayFromTheCorner)
{
    const Contact contact = hitbox::circleVsPolygon(Circle{{-3.f, 96.f}, 10.f}, ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(-0.6f, -0.8f));
    EXPECT_FLOAT_EQ(contact.depth, 5.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(0.f, 100.f));
}

TEST(CircleVsPolygon, ACentreInsideLeavesThroughTheNearestEdge)
{
    const Contact contact = hitbox::circleVsPolygon(Circle{{197.f, 120.f}, 4.f}, ground);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(1.f, 0.f));
    EXPECT_FLOAT_EQ(contact.depth, 7.f);
}

TEST(CircleVsPolygon, TouchingDoesNotCollide)
{
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{50.f, 90.f}, 10.f}, ground));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{-6.f, 92.f}, 10.f}, ground)); // at a corner
}

TEST(CircleVsPolygon, AZeroRadiusCircleIsAPoint)
{
    EXPECT_TRUE(hitbox::circleVsPolygon(Circle{{50.f, 110.f}, 0.f}, ground));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{50.f, 100.f}, 0.f}, ground));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{50.f, 100.f}, 0.f},
                                         Polygon{{{0.f, 100.f}, {90.f, 100.f}}}));
}

TEST(CircleVsPolygon, APolygonWithNoAreaCollidesWhenItReachesInside)
{
    const Polygon stick{{{0.f, 0.f}, {100.f, 0.f}}};
    EXPECT_TRUE(hitbox::circleVsPolygon(Circle{{50.f, 5.f}, 10.f}, stick));
    const Contact onIt = hitbox::circleVsPolygon(Circle{{50.f, 0.f}, 10.f}, stick);
    ASSERT_TRUE(onIt);
    EXPECT_FLOAT_EQ(onIt.depth, 10.f);
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{50.f, 10.f}, 10.f}, stick));
}

TEST(CircleVsPolygon, NegativeRadiusOrNaNNeverCollides)
{
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{50.f, 110.f}, -1.f}, ground));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{notANumber, 110.f}, 5.f}, ground));
    EXPECT_FALSE(hitbox::circleVsPolygon(Circle{{50.f, 110.f}, 5.f}, Polygon{}));
}

TEST(PointInPolygon, StrictlyInsideOnly)
{
    EXPECT_TRUE(hitbox::pointInPolygon({10.f, 110.f}, ground));
    EXPECT_TRUE(hitbox::pointInPolygon({10.f, 110.f}, reversed(ground)));
    EXPECT_FALSE(hitbox::pointInPolygon({10.f, 100.f}, ground));
    EXPECT_FALSE(hitbox::pointInPolygon({-1.f, 110.f}, ground));
    EXPECT_FALSE(hitbox::pointInPolygon({5.f, 5.f}, Polygon{{{0.f, 0.f}, {10.f, 10.f}}}));
}
