// Hidden variants of lab 5's grading tests: the same behaviour as RayGradingTests.cpp and
// RayCircleGradingTests.cpp with other numbers, directions and positions. The instructor's
// build and the class grader run them; the student handout leaves tests/labs-hidden/ out, so
// no one can tune an answer to them.
#include "labs/05_ray_caster/RayChecks.h"

#include "RayCircle.h"
#include "RayLevel.h"

#include "hitbox/geometry/Shapes.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/geometry/Vec2.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{

using namespace raychecks;

} // namespace

TEST(Task1NearestRayHit, HiddenNearestBoxInTheMiddleOfTheListOnARayGoingUpLeft)
{
    // Up and to the left, the nearest of four boxes listed third: keeping the first or the
    // last hit found picks another box, and the bottom face gives a normal pointing down.
    const RayLevel level({{150.f, 100.f, 60.f, 100.f},
                          {350.f, 200.f, 50.f, 60.f},
                          {650.f, 300.f, 100.f, 80.f},
                          {250.f, 120.f, 40.f, 40.f}},
                         {1000.f, 600.f});
    const RayHit ray = level.castRay({900.f, 500.f}, {100.f, 100.f});
    ASSERT_TRUE(ray.hit);
    EXPECT_EQ(ray.boxIndex, 2);
    EXPECT_NEAR(ray.end.x, 660.f, 0.01f);
    EXPECT_NEAR(ray.end.y, 380.f, 0.01f);
    EXPECT_EQ(ray.normal, hitbox::Vec2(0.f, 1.f));
    EXPECT_NEAR(ray.time, 0.3f, 1e-4f);
}

TEST(Task1NearestRayHit, HiddenNormalOfTheLeftFaceAndOfSlantedRays)
{
    // The face the visible tests reach only head-on, and the bottom face from a slant: the
    // normal is the face's, whatever the ray's direction.
    const RayLevel level({{200.f, 150.f, 60.f, 40.f}}, {1000.f, 600.f});
    const RayHit fromLeft = level.castRay({100.f, 160.f}, {300.f, 200.f});
    ASSERT_TRUE(fromLeft.hit);
    EXPECT_EQ(fromLeft.normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_NEAR(fromLeft.end.y, 180.f, 0.01f);
    EXPECT_NEAR(fromLeft.time, 0.5f, 1e-4f);
    const RayHit fromBelow = level.castRay({250.f, 290.f}, {210.f, 90.f});
    ASSERT_TRUE(fromBelow.hit);
    EXPECT_EQ(fromBelow.normal, hitbox::Vec2(0.f, 1.f));
    EXPECT_NEAR(fromBelow.end.x, 230.f, 0.01f);
    EXPECT_EQ(fromBelow.boxIndex, 0);
}

TEST(Task1NearestRayHit, HiddenRayThatStopsShortOrGrazesAnEdgeMisses)
{
    // Edge rule: a ray running along the top face only touches the box. A ray that ends
    // before the near box, with another box behind its start, hits nothing either.
    const RayLevel level({{500.f, 300.f, 100.f, 100.f}, {20.f, 300.f, 40.f, 300.f}},
                         {1000.f, 600.f});
    const RayHit grazing = level.castRay({450.f, 300.f}, {700.f, 300.f});
    EXPECT_FALSE(grazing.hit);
    EXPECT_EQ(grazing.end, hitbox::Vec2(700.f, 300.f));
    EXPECT_EQ(grazing.boxIndex, -1);
    const RayHit shortRay = level.castRay({100.f, 350.f}, {499.f, 380.f});
    EXPECT_FALSE(shortRay.hit);
    EXPECT_EQ(shortRay.end, hitbox::Vec2(499.f, 380.f));
}

TEST(Task1NearestRayHit, HiddenTheLevelCastsFromThePlayerOnASlant)
{
    // Player at the origin (centre (16, 16)), standing still, so whatever the step's move
    // (task 2) does it stays there; the mouse down and to the right, the far box listed first.
    RayLevel level({{350.f, 200.f, 100.f, 200.f}, {200.f, 100.f, 50.f, 200.f}}, {0.f, 0.f});
    level.setMoveDirection({0.f, 0.f});
    runWithMouse(level, {416.f, 316.f}, 1);
    ASSERT_TRUE(level.getRay().hit);
    EXPECT_EQ(level.getRay().start, hitbox::Vec2(16.f, 16.f));
    EXPECT_EQ(level.getRay().boxIndex, 1);
    EXPECT_NEAR(level.getRay().end.x, 200.f, 0.01f);
    EXPECT_NEAR(level.getRay().end.y, 154.f, 0.01f);
}

TEST(Task2MoveAndSlide, HiddenStopsTouchingACeilingWhenMovingUp)
{
    // Straight up into a ceiling: the box stops touching its underside, whichever way it moves.
    RayLevel level({{0.f, 40.f, 1200.f, 25.f}}, {300.f, 350.f});
    level.setMoveDirection({0.f, -1.f});
    runWithMouse(level, {0.f, 0.f}, 150); // 375 px up: far enough to pass the ceiling
    const hitbox::Box box = hitbox::toBox(level.getPlayer().getCollisionBox());
    EXPECT_NEAR(box.top, 65.f, 0.01f);
    EXPECT_NEAR(box.left, 300.f, 0.01f);
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2MoveAndSlide, HiddenSlidesUpAWallOnItsLeft)
{
    // Up and to the left into a long wall: it reaches the wall after about 1.3 s and then
    // keeps the whole upward part of its speed.
    RayLevel level({{100.f, 0.f, 20.f, 700.f}}, {400.f, 600.f});
    level.setMoveDirection({-1.f, -1.f});
    runWithMouse(level, {0.f, 0.f}, 180);
    const hitbox::Vec2 position = hitbox::toVec2(level.getPlayer().getPosition());
    EXPECT_NEAR(position.x, 120.f, 0.01f) << "resting against the wall";
    EXPECT_NEAR(position.y, 600.f - diagonalSpeed * 1.5f, 1.f) << "never slowed down";
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2MoveAndSlide, HiddenSlidesUpTheSeamsOfATiledWall)
{
    // Pressed right into a tiled wall while moving up, starting exactly on a seam (y = 520,
    // a tie between two tiles): the seams of a wall, not only of a floor, are slid over. The
    // wall runs from y = 0 to 680 with its left side at x = 800, stored top to bottom (as the
    // lab's own right wall is).
    RayLevel level(tileLine({800.f, 0.f}, {0.f, 40.f}, 17), {768.f, 520.f});
    level.setTimeOrder(true);
    level.setMoveDirection({1.f, -1.f});
    runWithMouse(level, {0.f, 0.f}, 120);
    EXPECT_NEAR(level.getPlayer().getPosition().x, 768.f, 0.01f);
    EXPECT_NEAR(level.getPlayer().getPosition().y, 520.f - diagonalSpeed, 1.f)
        << "crossed the seams without slowing down";
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task2MoveAndSlide, HiddenWithoutTimeOrderTheBoxSnagsOnTheSeamAhead)
{
    // Moving down-right over a floor stored right to left: in list order the corner of the
    // tile ahead is handled before the tile underneath, and the box stops at the seam x = 680.
    RayLevel level(tileLine({1160.f, 600.f}, {-40.f, 0.f}, 30), {630.f, 568.f});
    level.setTimeOrder(false);
    level.setMoveDirection({1.f, 1.f});
    runWithMouse(level, {0.f, 0.f}, 120);
    EXPECT_NEAR(level.getPlayer().getPosition().x, 648.f, 0.01f);
    EXPECT_NEAR(level.getPlayer().getPosition().y, 568.f, 0.01f);
}

TEST(Task2MoveAndSlide, HiddenTheHitsAreKeptNearestFirstInAnUpperCorner)
{
    // Up-right into a corner in one step: the ceiling (0.5 px away) is reached before the
    // wall (1.5 px away), though the wall comes first in the list.
    RayLevel level({{700.f, 0.f, 100.f, 700.f}, {0.f, 0.f, 1200.f, 100.f}}, {666.5f, 100.5f});
    level.setTimeOrder(true);
    level.setMoveDirection({1.f, -1.f});
    runWithMouse(level, {0.f, 0.f}, 1);
    const std::vector<hitbox::Hit>& hits = level.getLastHits();
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].normal, hitbox::Vec2(0.f, 1.f)) << "the ceiling first";
    EXPECT_EQ(hits[1].normal, hitbox::Vec2(-1.f, 0.f));
    EXPECT_LE(hits[0].time, hits[1].time);
    EXPECT_FALSE(overlapsAnySolid(level));
}

TEST(Task3Stuck, HiddenHardlyMovingInAnyDirectionIsStuck)
{
    // Down, diagonally and a quarter pixel up: only the ratio of the lengths counts, not the
    // direction of either move nor how small the step is.
    EXPECT_TRUE(isSnagged({0.f, 3.f}, {0.29f, 0.f}));
    EXPECT_TRUE(isSnagged({-2.f, -2.f}, {0.1f, -0.2f})); // 0.05 against 0.08, squared
    EXPECT_TRUE(isSnagged({0.f, -0.25f}, {0.f, 0.f}));
}

TEST(Task3Stuck, HiddenSlidingUpOrSlowlyIsNotStuck)
{
    // Sliding up a wall, a slow step that still gets more than a tenth of the way, a free move.
    EXPECT_FALSE(isSnagged({3.f, -3.f}, {0.f, -3.f}));
    EXPECT_FALSE(isSnagged({0.f, -0.5f}, {0.f, -0.06f}));
    EXPECT_FALSE(isSnagged({-7.f, 1.f}, {-7.f, 1.f})); // moved all the way
}

TEST(Task3Stuck, HiddenExactlyATenthIsNotStuckWhateverTheDirection)
{
    // Whole numbers, so the squared lengths are exact: 4 against a tenth of 20, squared.
    EXPECT_FALSE(isSnagged({0.f, 20.f}, {0.f, 2.f}));
    EXPECT_FALSE(isSnagged({-12.f, 16.f}, {2.f, 0.f})) << "only the lengths count";
    EXPECT_TRUE(isSnagged({-12.f, 16.f}, {0.f, 1.96f}));
    EXPECT_TRUE(isSnagged({0.f, 20.f}, {-1.99f, 0.f}));
}

TEST(Task4RayAgainstCircle, HiddenADiagonalOrUpwardRayEntersAtTheNearRim)
{
    // A pillar of radius 25 away from the origin (so `f` must be measured from its centre):
    // a ray through the centre enters 25 px before it, from either end and going up.
    const hitbox::Circle pillar{{200.f, 100.f}, 25.f};
    EXPECT_FLOAT_EQ(rayCircleTime({140.f, 20.f}, {260.f, 180.f}, pillar), 0.375f);
    EXPECT_FLOAT_EQ(rayCircleTime({260.f, 180.f}, {140.f, 20.f}, pillar), 0.375f);
    EXPECT_FLOAT_EQ(rayCircleTime({200.f, 160.f}, {200.f, 60.f}, pillar), 0.35f);
}

TEST(Task4RayAgainstCircle, HiddenAnOffCentreRayEntersWhereTheChordStarts)
{
    const hitbox::Circle pillar{{200.f, 100.f}, 25.f};
    // 7 px off the centre the half chord is 24 (7-24-25); 15 px off it is 20 (15-20-25).
    EXPECT_FLOAT_EQ(rayCircleTime({150.f, 107.f}, {250.f, 107.f}, pillar), 0.26f);
    EXPECT_FLOAT_EQ(rayCircleTime({185.f, 200.f}, {185.f, 0.f}, pillar), 0.4f);
}

TEST(Task4RayAgainstCircle, HiddenRaysBesideAwayOrShortMiss)
{
    const hitbox::Circle pillar{{200.f, 100.f}, 25.f};
    EXPECT_EQ(rayCircleTime({100.f, 74.f}, {300.f, 74.f}, pillar), rayMissed);   // beside
    EXPECT_EQ(rayCircleTime({260.f, 100.f}, {300.f, 120.f}, pillar), rayMissed); // away
    EXPECT_EQ(rayCircleTime({200.f, 20.f}, {200.f, 70.f}, pillar), rayMissed);   // short
    // Its line crosses the pillar behind the start: no negative times.
    EXPECT_EQ(rayCircleTime({200.f, 200.f}, {200.f, 200.0625f}, pillar), rayMissed);
}

// Edge rule: touching is not colliding.
TEST(Task4RayAgainstCircle, HiddenGrazingOrReachingTheRimAtTheEndMisses)
{
    const hitbox::Circle pillar{{200.f, 100.f}, 25.f};
    EXPECT_EQ(rayCircleTime({100.f, 125.f}, {300.f, 125.f}, pillar), rayMissed);
    // Along the tangent at (215, 120), slanted: the discriminant is exactly 0.
    EXPECT_EQ(rayCircleTime({255.f, 90.f}, {175.f, 150.f}, pillar), rayMissed);
    EXPECT_GE(rayCircleTime({100.f, 124.f}, {300.f, 124.f}, pillar), 0.f); // a pixel inside
    EXPECT_EQ(rayCircleTime({140.f, 100.f}, {175.f, 100.f}, pillar), rayMissed);
    EXPECT_FLOAT_EQ(rayCircleTime({140.f, 100.f}, {177.f, 100.f}, pillar), 35.f / 37.f);
}

TEST(Task4RayAgainstCircle, HiddenStartingInsideOrOnTheRim)
{
    const hitbox::Circle pillar{{200.f, 100.f}, 25.f};
    EXPECT_EQ(rayCircleTime({210.f, 90.f}, {400.f, 90.f}, pillar), 0.f);
    EXPECT_EQ(rayCircleTime({190.f, 110.f}, {190.f, 110.f}, pillar), 0.f); // inside, still
    // (215, 120) is on the rim: in, out, along the tangent, not moving.
    EXPECT_EQ(rayCircleTime({215.f, 120.f}, {185.f, 80.f}, pillar), 0.f);
    EXPECT_EQ(rayCircleTime({215.f, 120.f}, {245.f, 160.f}, pillar), rayMissed);
    EXPECT_EQ(rayCircleTime({215.f, 120.f}, {255.f, 90.f}, pillar), rayMissed);
    EXPECT_EQ(rayCircleTime({215.f, 120.f}, {215.f, 120.f}, pillar), rayMissed);
}

TEST(Task4RayAgainstCircle, HiddenAZeroOrNegativeRadiusIsNeverHitAnywhere)
{
    // A radius of -25 squares to 625, as 25 does: only the radius check stops the last two.
    EXPECT_EQ(rayCircleTime({100.f, 100.f}, {300.f, 100.f}, {{200.f, 100.f}, 0.f}), rayMissed);
    EXPECT_EQ(rayCircleTime({100.f, 100.f}, {300.f, 100.f}, {{200.f, 100.f}, -25.f}), rayMissed);
    EXPECT_EQ(rayCircleTime({200.f, 100.f}, {300.f, 100.f}, {{200.f, 100.f}, -25.f}), rayMissed);
}
