// ResponseTest.cpp - slide, bounce, push out and elastic collisions (Response.h).
#include "hitbox/geometry/Response.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Sweep.h"
#include "support/Printers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using hitbox::Hit;

namespace
{
Hit floorHitAt(float time)
{
    Hit hit;
    hit.hit = true;
    hit.time = time;
    hit.normal = {0.f, -1.f};
    return hit;
}
} // namespace

TEST(SlideVelocity, KeepsTheMotionAlongTheSurfaceAndStopsAtIt)
{
    // Falling at 100 px/s onto a floor reached a quarter of the way into the step.
    const hitbox::Vec2 slid = hitbox::slideVelocity({40.f, 100.f}, floorHitAt(0.25f));
    EXPECT_FLOAT_EQ(slid.x, 40.f); // along the floor: untouched
    EXPECT_FLOAT_EQ(slid.y, 25.f); // only the part before the impact is left
}

TEST(SlideVelocity, MovingByTheResultEndsTouchingTheSurface)
{
    const hitbox::Box box(0.f, 0.f, 20.f, 20.f);
    const hitbox::Box floor(-100.f, 50.f, 400.f, 20.f);
    const hitbox::Vec2 velocity(300.f, 600.f);
    const float dt = 0.1f;
    const Hit hit = hitbox::sweepBoxVsBox(box, velocity * dt, floor);
    ASSERT_TRUE(hit);
    const hitbox::Vec2 slid = hitbox::slideVelocity(velocity, hit);
    EXPECT_FLOAT_EQ(box.top + box.height + slid.y * dt, floor.top);
    EXPECT_FLOAT_EQ(slid.x, velocity.x);
}

TEST(SlideVelocity, NoHitOrMovingAwayChangesNothing)
{
    EXPECT_EQ(hitbox::slideVelocity({40.f, 100.f}, Hit{}), hitbox::Vec2(40.f, 100.f));
    EXPECT_EQ(hitbox::slideVelocity({40.f, -100.f}, floorHitAt(0.f)), hitbox::Vec2(40.f, -100.f));
}

TEST(SlideVelocity, StartedInsideRemovesTheWholeInwardPart)
{
    Hit inside = floorHitAt(0.f);
    inside.startedInside = true;
    EXPECT_EQ(hitbox::slideVelocity({40.f, 100.f}, inside), hitbox::Vec2(40.f, 0.f));
}

TEST(BounceVelocity, ReflectsWithRestitution)
{
    EXPECT_EQ(hitbox::bounceVelocity({30.f, 100.f}, {0.f, -1.f}, 1.f), hitbox::Vec2(30.f, -100.f));
    EXPECT_EQ(hitbox::bounceVelocity({30.f, 100.f}, {0.f, -1.f}, 0.5f), hitbox::Vec2(30.f, -50.f));
    EXPECT_EQ(hitbox::bounceVelocity({30.f, 100.f}, {0.f, -1.f}, 0.f), hitbox::Vec2(30.f, 0.f));
}

TEST(BounceVelocity, ADiagonalSurfaceTurnsTheVelocity)
{
    const float d = std::sqrt(0.5f);
    const hitbox::Vec2 bounced = hitbox::bounceVelocity({100.f, 0.f}, {-d, -d}, 1.f);
    EXPECT_NEAR(bounced.x, 0.f, 1e-4f);
    EXPECT_NEAR(bounced.y, -100.f, 1e-4f);
}

TEST(BounceVelocity, LeavingOrNoNormalChangesNothingAndRestitutionIsClamped)
{
    EXPECT_EQ(hitbox::bounceVelocity({30.f, -100.f}, {0.f, -1.f}, 1.f), hitbox::Vec2(30.f, -100.f));
    EXPECT_EQ(hitbox::bounceVelocity({30.f, 100.f}, {0.f, 0.f}, 1.f), hitbox::Vec2(30.f, 100.f));
    EXPECT_EQ(hitbox::bounceVelocity({30.f, 100.f}, {0.f, -1.f}, 5.f), hitbox::Vec2(30.f, -100.f));
    EXPECT_EQ(hitbox::bounceVelocity({30.f, 100.f}, {0.f, -1.f}, -2.f), hitbox::Vec2(30.f, 0.f));
}

TEST(PushOutOffset, MovesAJustClearOfB)
{
    const hitbox::Box a(95.f, 0.f, 10.f, 10.f);
    const hitbox::Box b(100.f, 0.f, 50.f, 50.f);
    const hitbox::Contact contact = hitbox::boxVsBoxContact(a, b);
    const hitbox::Vec2 offset = hitbox::pushOutOffset(contact);
    // The depth, 5 px, rounded outward by pushOutSlop of the contact's scale (100 px).
    EXPECT_LE(offset.x, -5.f);
    EXPECT_NEAR(offset.x, -5.f, 100.f * hitbox::pushOutSlop * 1.01f);
    EXPECT_EQ(offset.y, 0.f);
    EXPECT_FALSE(hitbox::boxVsBox({a.left + offset.x, a.top + offset.y, a.width, a.height}, b));
    EXPECT_EQ(hitbox::pushOutOffset(hitbox::Contact{}), hitbox::Vec2(0.f, 0.f));
}

// Issue 25, item 2: a push of exactly the float depth often left the pair overlapping by
// about 1e-6 px (these two circles).
TEST(PushOutOffset, ThePairNoLongerCollidesAfterIt)
{
    const hitbox::Circle a{{-17.f, -11.f}, 16.f};
    const hitbox::Circle b{{-7.f, -3.f}, 20.f};
    const hitbox::Contact circles = hitbox::circleVsCircleContact(a, b);
    ASSERT_TRUE(circles.hit);
    EXPECT_FALSE(
        hitbox::circleVsCircleContact({a.center + hitbox::pushOutOffset(circles), a.radius}, b)
            .hit);
}

TEST(ElasticCollision, EqualMassesSwapTheirSpeedsAlongTheNormal)
{
    // First on the left moving right, second on the right moving left: the normal points
    // out of the second towards the first, (-1, 0).
    const auto after = hitbox::elasticCollision({100.f, 5.f}, 1.f, {-50.f, 0.f}, 1.f, {-1.f, 0.f});
    EXPECT_FLOAT_EQ(after.first.x, -50.f);
    EXPECT_FLOAT_EQ(after.first.y, 5.f); // across the normal: untouched
    EXPECT_FLOAT_EQ(after.second.x, 100.f);
}

TEST(ElasticCollision, KeepsMomentumAndEnergy)
{
    const hitbox::Vec2 normal(-0.6f, -0.8f);
    const auto after = hitbox::elasticCollision({120.f, 90.f}, 2.f, {-10.f, -30.f}, 5.f, normal);
    const hitbox::Vec2 momentumBefore =
        hitbox::Vec2(120.f, 90.f) * 2.f + hitbox::Vec2(-10.f, -30.f) * 5.f;
    const hitbox::Vec2 momentumAfter = after.first * 2.f + after.second * 5.f;
    EXPECT_NEAR(momentumAfter.x, momentumBefore.x, 1e-3f);
    EXPECT_NEAR(momentumAfter.y, momentumBefore.y, 1e-3f);
    const auto energy = [](hitbox::Vec2 v, float m) { return 0.5f * m * (v.x * v.x + v.y * v.y); };
    EXPECT_NEAR(energy(after.first, 2.f) + energy(after.second, 5.f),
                energy({120.f, 90.f}, 2.f) + energy({-10.f, -30.f}, 5.f), 0.5f);
}

TEST(ElasticCollision, AnInfiniteMassIsAWall)
{
    const float infinite = std::numeric_limits<float>::infinity();
    const auto after =
        hitbox::elasticCollision({100.f, 20.f}, 1.f, {0.f, 0.f}, infinite, {-1.f, 0.f});
    EXPECT_EQ(after.first, hitbox::Vec2(-100.f, 20.f));
    EXPECT_EQ(after.second, hitbox::Vec2(0.f, 0.f));
}

TEST(ElasticCollision, SeparatingOrInvalidMassesChangeNothing)
{
    const auto apart = hitbox::elasticCollision({-100.f, 0.f}, 1.f, {50.f, 0.f}, 1.f, {-1.f, 0.f});
    EXPECT_EQ(apart.first, hitbox::Vec2(-100.f, 0.f));
    const auto zero = hitbox::elasticCollision({100.f, 0.f}, 0.f, {-50.f, 0.f}, 1.f, {-1.f, 0.f});
    EXPECT_EQ(zero.first, hitbox::Vec2(100.f, 0.f));
    const auto nan = hitbox::elasticCollision({100.f, 0.f}, std::numeric_limits<float>::quiet_NaN(),
                                              {-50.f, 0.f}, 1.f, {-1.f, 0.f});
    EXPECT_EQ(nan.second, hitbox::Vec2(-50.f, 0.f));
    // 1 / 1e-40 overflows to infinity in float: unchanged, not NaN.
    const auto tiny =
        hitbox::elasticCollision({100.f, 0.f}, 1e-40f, {-50.f, 0.f}, 1.f, {-1.f, 0.f});
    EXPECT_EQ(tiny.first, hitbox::Vec2(100.f, 0.f));
    EXPECT_EQ(tiny.second, hitbox::Vec2(-50.f, 0.f));
}

TEST(ElasticCollision, RestitutionZeroLeavesThemMovingTogether)
{
    const auto after =
        hitbox::elasticCollision({100.f, 0.f}, 1.f, {0.f, 0.f}, 1.f, {-1.f, 0.f}, 0.f);
    EXPECT_FLOAT_EQ(after.first.x, 50.f);
    EXPECT_FLOAT_EQ(after.second.x, 50.f);
}
