// CapsuleTest.cpp - capsules (Capsule.h): closest points and the edge rules, one test each.
// Random agreement with a separate distance computation is in AgreementTest.cpp.
#include "hitbox/geometry/Capsule.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using hitbox::Capsule;
using hitbox::Circle;
using hitbox::closestPointOnSegment;
using hitbox::Contact;

namespace
{
const float notANumber = std::numeric_limits<float>::quiet_NaN();
const Capsule bar{{0.f, 0.f}, {100.f, 0.f}, 10.f}; // lying along the x axis
} // namespace

TEST(ClosestPointOnSegment, IsTheShadowKeptOnTheSegment)
{
    EXPECT_EQ(closestPointOnSegment({30.f, 40.f}, {0.f, 0.f}, {100.f, 0.f}),
              hitbox::Vec2(30.f, 0.f));
    EXPECT_EQ(closestPointOnSegment({-30.f, 40.f}, {0.f, 0.f}, {100.f, 0.f}),
              hitbox::Vec2(0.f, 0.f));
    EXPECT_EQ(closestPointOnSegment({130.f, -5.f}, {0.f, 0.f}, {100.f, 0.f}),
              hitbox::Vec2(100.f, 0.f));
}

TEST(ClosestPointOnSegment, ASegmentWithNoLengthIsItsStart)
{
    EXPECT_EQ(closestPointOnSegment({30.f, 40.f}, {5.f, 5.f}, {5.f, 5.f}), hitbox::Vec2(5.f, 5.f));
}

TEST(ClosestPointsOfSegments, CrossingSegmentsMeetAtTheCrossing)
{
    const auto points =
        hitbox::closestPointsOfSegments({0.f, 0.f}, {10.f, 10.f}, {0.f, 10.f}, {10.f, 0.f});
    EXPECT_NEAR(points.first.x, 5.f, 1e-5f);
    EXPECT_NEAR(points.second.y, 5.f, 1e-5f);
}

TEST(ClosestPointsOfSegments, AnEndAgainstTheMiddleOfTheOther)
{
    const auto points =
        hitbox::closestPointsOfSegments({50.f, 5.f}, {50.f, 30.f}, {0.f, 0.f}, {100.f, 0.f});
    EXPECT_EQ(points.first, hitbox::Vec2(50.f, 5.f));
    EXPECT_EQ(points.second, hitbox::Vec2(50.f, 0.f));
}

TEST(CapsuleVsCircle, NearTheSidePushesStraightAway)
{
    // A = the capsule: the normal points out of the circle towards the capsule.
    const Contact contact = hitbox::capsuleVsCircle(bar, Circle{{40.f, 15.f}, 10.f});
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(contact.depth, 5.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(40.f, 5.f)); // on the circle's rim
}

TEST(CapsuleVsCircle, NearARoundEndPushesAwayFromTheEnd)
{
    // The circle's centre is 20 px from the end (100, 0), along (0.6, 0.8); radii add to 25.
    const Contact contact = hitbox::capsuleVsCircle(bar, Circle{{112.f, 16.f}, 15.f});
    ASSERT_TRUE(contact);
    EXPECT_NEAR(contact.normal.x, -0.6f, 1e-6f);
    EXPECT_NEAR(contact.normal.y, -0.8f, 1e-6f);
    EXPECT_NEAR(contact.depth, 5.f, 1e-5f);
}

TEST(CapsuleVsCircle, TouchingDoesNotCollide)
{
    EXPECT_FALSE(hitbox::capsuleVsCircle(bar, Circle{{50.f, 20.f}, 10.f}));
    EXPECT_FALSE(hitbox::capsuleVsCircle(bar, Circle{{-20.f, 0.f}, 10.f}));
}

TEST(CapsuleVsCircle, ACentreOnTheCoreLeavesSideways)
{
    const Contact contact = hitbox::capsuleVsCircle(bar, Circle{{50.f, 0.f}, 4.f});
    ASSERT_TRUE(contact);
    EXPECT_EQ(std::fabs(contact.normal.y), 1.f);
    EXPECT_FLOAT_EQ(contact.depth, 14.f);
}

TEST(CapsuleVsCircle, ZeroRadiusMeansASegmentOrAPoint)
{
    const Capsule stick{{0.f, 0.f}, {100.f, 0.f}, 0.f};
    EXPECT_TRUE(hitbox::capsuleVsCircle(stick, Circle{{50.f, 3.f}, 5.f}));
    EXPECT_FALSE(hitbox::capsuleVsCircle(stick, Circle{{50.f, 5.f}, 5.f}));
    EXPECT_FALSE(hitbox::capsuleVsCircle(stick, Circle{{50.f, 0.f}, 0.f})); // no area either side
    // A capsule with no length is a circle.
    EXPECT_TRUE(
        hitbox::capsuleVsCircle(Capsule{{0.f, 0.f}, {0.f, 0.f}, 5.f}, Circle{{9.f, 0.f}, 5.f}));
    EXPECT_FALSE(
        hitbox::capsuleVsCircle(Capsule{{0.f, 0.f}, {0.f, 0.f}, 5.f}, Circle{{10.f, 0.f}, 5.f}));
}

TEST(CapsuleVsCircle, NegativeRadiusOrNaNNeverCollides)
{
    EXPECT_FALSE(
        hitbox::capsuleVsCircle(Capsule{{0.f, 0.f}, {100.f, 0.f}, -1.f}, Circle{{50.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::capsuleVsCircle(Capsule{{notANumber, 0.f}, {100.f, 0.f}, 5.f},
                                         Circle{{50.f, 0.f}, 5.f}));
    EXPECT_FALSE(hitbox::capsuleVsCircle(bar, Circle{{50.f, notANumber}, 5.f}));
}

TEST(CapsuleVsCapsule, ParallelCapsulesPushApartAcross)
{
    const Contact contact =
        hitbox::capsuleVsCapsule(Capsule{{20.f, 15.f}, {80.f, 15.f}, 10.f}, bar);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, 1.f));
    EXPECT_FLOAT_EQ(contact.depth, 5.f);
}

TEST(CapsuleVsCapsule, EndToSideUsesTheClosestPoints)
{
    // Standing on the bar: its lower end is 10 px from the bar's core, radii add to 14.
    const Capsule standing{{50.f, 10.f}, {50.f, 60.f}, 4.f};
    const Contact contact = hitbox::capsuleVsCapsule(standing, bar);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, 1.f));
    EXPECT_FLOAT_EQ(contact.depth, 4.f);
    EXPECT_EQ(contact.point, hitbox::Vec2(50.f, 10.f)); // on B's surface
}

TEST(CapsuleVsCapsule, TouchingDoesNotCollide)
{
    EXPECT_FALSE(hitbox::capsuleVsCapsule(Capsule{{20.f, 20.f}, {80.f, 20.f}, 10.f}, bar));
    EXPECT_FALSE(hitbox::capsuleVsCapsule(Capsule{{120.f, 0.f}, {200.f, 0.f}, 10.f}, bar));
}

TEST(CapsuleVsCapsule, CrossingCoresArePushedClearOfTheOther)
{
    // A crosses B's core: move A across B's line until its whole core is the radii away.
    const Capsule crossing{{50.f, -30.f}, {60.f, 20.f}, 5.f};
    const Contact contact = hitbox::capsuleVsCapsule(crossing, bar);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f)); // A's middle is above B's line
    EXPECT_FLOAT_EQ(contact.depth, 15.f + 20.f);        // its lower end is 20 px below
    const Capsule moved{crossing.start + contact.normal * contact.depth,
                        crossing.end + contact.normal * contact.depth, 5.f};
    EXPECT_FALSE(hitbox::capsuleVsCapsule(moved, bar));
}

TEST(CapsuleVsCapsule, TwoSegmentsNeverCollide)
{
    EXPECT_FALSE(hitbox::capsuleVsCapsule(Capsule{{50.f, -30.f}, {50.f, 30.f}, 0.f},
                                          Capsule{{0.f, 0.f}, {100.f, 0.f}, 0.f}));
}

TEST(CapsuleVsCapsule, SwappingReversesTheNormal)
{
    const Capsule a{{20.f, 15.f}, {80.f, 25.f}, 10.f};
    const Contact ab = hitbox::capsuleVsCapsule(a, bar);
    const Contact ba = hitbox::capsuleVsCapsule(bar, a);
    ASSERT_TRUE(ab);
    ASSERT_TRUE(ba);
    EXPECT_NEAR(ab.normal.x, -ba.normal.x, 1e-5f);
    EXPECT_NEAR(ab.normal.y, -ba.normal.y, 1e-5f);
    EXPECT_NEAR(ab.depth, ba.depth, 1e-4f);
}

TEST(CapsuleVsPolygon, ResolvesAgainstAFace)
{
    const hitbox::Polygon floor = hitbox::toPolygon(hitbox::Box(0.f, 100.f, 200.f, 50.f));
    const Contact contact =
        hitbox::capsuleVsPolygon(Capsule{{20.f, 95.f}, {80.f, 95.f}, 8.f}, floor);
    ASSERT_TRUE(contact);
    EXPECT_EQ(contact.normal, hitbox::Vec2(0.f, -1.f));
    EXPECT_FLOAT_EQ(contact.depth, 3.f);
    EXPECT_FLOAT_EQ(contact.point.y, 100.f);
}

TEST(CapsuleVsPolygon, ARoundEndNearACornerUsesTheCornerDirection)
{
    const hitbox::Polygon floor = hitbox::toPolygon(hitbox::Box(0.f, 100.f, 200.f, 50.f));
    // End 5 px from the corner (0, 100) along (-0.6, -0.8), radius 8: 3 px in.
    const Contact contact =
        hitbox::capsuleVsPolygon(Capsule{{-3.f, 96.f}, {-60.f, 96.f}, 8.f}, floor);
    ASSERT_TRUE(contact);
    EXPECT_NEAR(contact.normal.x, -0.6f, 1e-5f);
    EXPECT_NEAR(contact.normal.y, -0.8f, 1e-5f);
    EXPECT_NEAR(contact.depth, 3.f, 1e-4f);
}

TEST(CapsuleVsPolygon, TouchingDoesNotCollide)
{
    const hitbox::Polygon floor = hitbox::toPolygon(hitbox::Box(0.f, 100.f, 200.f, 50.f));
    EXPECT_FALSE(hitbox::capsuleVsPolygon(Capsule{{20.f, 92.f}, {80.f, 92.f}, 8.f}, floor));
}

TEST(CapsuleVsPolygon, ZeroRadiusIsASegmentThatMustReachInside)
{
    const hitbox::Polygon floor = hitbox::toPolygon(hitbox::Box(0.f, 100.f, 200.f, 50.f));
    EXPECT_TRUE(hitbox::capsuleVsPolygon(Capsule{{50.f, 90.f}, {50.f, 110.f}, 0.f}, floor));
    EXPECT_FALSE(hitbox::capsuleVsPolygon(Capsule{{0.f, 100.f}, {300.f, 100.f}, 0.f},
                                          floor)); // along an edge
    EXPECT_FALSE(
        hitbox::capsuleVsPolygon(Capsule{{50.f, 90.f}, {50.f, 110.f}, 0.f},
                                 hitbox::Polygon{{{0.f, 100.f}, {100.f, 100.f}}})); // no area
}

TEST(CapsuleVsPolygon, EmptyNaNOrNegativeRadiusNeverCollides)
{
    const hitbox::Polygon floor = hitbox::toPolygon(hitbox::Box(0.f, 100.f, 200.f, 50.f));
    EXPECT_FALSE(
        hitbox::capsuleVsPolygon(Capsule{{20.f, 95.f}, {80.f, 95.f}, 8.f}, hitbox::Polygon{}));
    EXPECT_FALSE(hitbox::capsuleVsPolygon(Capsule{{20.f, 95.f}, {80.f, 95.f}, -8.f}, floor));
    EXPECT_FALSE(hitbox::capsuleVsPolygon(Capsule{{notANumber, 95.f}, {80.f, 95.f}, 8.f}, floor));
}
