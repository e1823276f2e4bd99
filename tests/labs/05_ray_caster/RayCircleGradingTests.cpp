// Grading tests of lab 5, task 4 (a ray against a circle): rayCircleTime on its own, so no
// other task's code runs. The numbers are whole, so float arithmetic is exact: a ray that
// grazes the rim gives a discriminant of exactly 0, and the touching cases are certain.
#include "RayCircle.h"

#include <gtest/gtest.h>

namespace
{
const hitbox::Circle pillar{{0.f, 0.f}, 10.f}; // radius 10 about the origin
}

TEST(Task4RayAgainstCircle, AHeadOnRayEntersAtTheNearRim)
{
    // From x = -20 to x = 20: the rim is at x = -10, a quarter of the way.
    EXPECT_FLOAT_EQ(rayCircleTime({-20.f, 0.f}, {20.f, 0.f}, pillar), 0.25f);
    // The other way round it enters at x = 10.
    EXPECT_FLOAT_EQ(rayCircleTime({30.f, 0.f}, {-10.f, 0.f}, pillar), 0.5f);
    // Downwards.
    EXPECT_FLOAT_EQ(rayCircleTime({0.f, -50.f}, {0.f, 50.f}, pillar), 0.4f);
}

TEST(Task4RayAgainstCircle, AnOffCentreRayEntersWhereTheChordStarts)
{
    // At y = 6 the rim is at x = -8 (a 6-8-10 triangle).
    EXPECT_FLOAT_EQ(rayCircleTime({-18.f, 6.f}, {22.f, 6.f}, pillar), 0.25f);
    EXPECT_FLOAT_EQ(rayCircleTime({-18.f, -6.f}, {22.f, -6.f}, pillar), 0.25f);
}

TEST(Task4RayAgainstCircle, ARayThatPassesBesideMisses)
{
    EXPECT_EQ(rayCircleTime({-20.f, 11.f}, {20.f, 11.f}, pillar), rayMissed);
    EXPECT_EQ(rayCircleTime({-20.f, 20.f}, {20.f, 30.f}, pillar), rayMissed);
}

TEST(Task4RayAgainstCircle, ARayPointingAwayOrStoppingShortMisses)
{
    EXPECT_EQ(rayCircleTime({20.f, 0.f}, {40.f, 0.f}, pillar), rayMissed);   // away
    EXPECT_EQ(rayCircleTime({-40.f, 0.f}, {-20.f, 0.f}, pillar), rayMissed); // short
}

// Edge rule: touching is not colliding.
TEST(Task4RayAgainstCircle, AGrazingRayMisses)
{
    EXPECT_EQ(rayCircleTime({-20.f, 10.f}, {20.f, 10.f}, pillar), rayMissed);
    EXPECT_EQ(rayCircleTime({10.f, -20.f}, {10.f, 20.f}, pillar), rayMissed);
    EXPECT_GE(rayCircleTime({-20.f, 9.f}, {20.f, 9.f}, pillar), 0.f); // a pixel inside: hits
}

TEST(Task4RayAgainstCircle, ReachingTheRimOnlyAtTheEndMisses)
{
    EXPECT_EQ(rayCircleTime({-20.f, 0.f}, {-10.f, 0.f}, pillar), rayMissed);
    EXPECT_FLOAT_EQ(rayCircleTime({-20.f, 0.f}, {-8.f, 0.f}, pillar), 10.f / 12.f);
}

TEST(Task4RayAgainstCircle, StartingInsideIsTimeZero)
{
    EXPECT_EQ(rayCircleTime({0.f, 0.f}, {20.f, 0.f}, pillar), 0.f);
    EXPECT_EQ(rayCircleTime({3.f, 4.f}, {-30.f, 4.f}, pillar), 0.f);
    EXPECT_EQ(rayCircleTime({3.f, 4.f}, {3.f, 4.f}, pillar), 0.f); // not moving, inside
}

TEST(Task4RayAgainstCircle, StartingOnTheRimHitsOnlyWhenHeadingIn)
{
    EXPECT_EQ(rayCircleTime({-10.f, 0.f}, {10.f, 0.f}, pillar), 0.f);
    EXPECT_EQ(rayCircleTime({-10.f, 0.f}, {-20.f, 0.f}, pillar), rayMissed); // heading out
    EXPECT_EQ(rayCircleTime({-10.f, 0.f}, {-10.f, 8.f}, pillar), rayMissed); // along the tangent
    EXPECT_EQ(rayCircleTime({6.f, 8.f}, {6.f, 8.f}, pillar), rayMissed);     // not moving
}

TEST(Task4RayAgainstCircle, AZeroOrNegativeRadiusIsNeverHit)
{
    EXPECT_EQ(rayCircleTime({-20.f, 0.f}, {20.f, 0.f}, {{0.f, 0.f}, 0.f}), rayMissed);
    EXPECT_EQ(rayCircleTime({-20.f, 0.f}, {20.f, 0.f}, {{0.f, 0.f}, -10.f}), rayMissed);
    EXPECT_EQ(rayCircleTime({0.f, 0.f}, {20.f, 0.f}, {{0.f, 0.f}, -10.f}), rayMissed);
}

TEST(Task4RayAgainstCircle, ASmallPillarAndAShortRayWork)
{
    // A ray 1 px long against a pillar of radius 1: enters halfway, at x = -1.
    EXPECT_FLOAT_EQ(rayCircleTime({-1.5f, 0.f}, {-0.5f, 0.f}, {{0.f, 0.f}, 1.f}), 0.5f);
    EXPECT_FLOAT_EQ(rayCircleTime({-2.f, 0.f}, {2.f, 0.f}, {{0.f, 0.f}, 0.5f}), 0.375f);
}

TEST(Task4RayAgainstCircle, AShortRayHeadingAwayMisses)
{
    // Its line crosses the pillar, but behind the start: no negative times.
    EXPECT_EQ(rayCircleTime({20.f, 0.f}, {20.03125f, 0.f}, pillar), rayMissed);
    EXPECT_EQ(rayCircleTime({0.f, 20.f}, {0.f, 20.03125f}, pillar), rayMissed);
}

TEST(Task4RayAgainstCircle, APillarAnywhereWorks)
{
    const hitbox::Circle far{{620.f, -320.f}, 30.f};
    EXPECT_FLOAT_EQ(rayCircleTime({500.f, -320.f}, {700.f, -320.f}, far), 0.45f);
    EXPECT_FLOAT_EQ(rayCircleTime({620.f, -200.f}, {620.f, -400.f}, far), 0.45f);
}
