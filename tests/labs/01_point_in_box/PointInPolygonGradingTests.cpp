// Grading tests of lab 1, task 4 (point in a polygon): isInsidePolygon on its own, so no
// other task's code runs. The touching cases use whole-number corners and edges along the
// axes or at 45 degrees, where float arithmetic is exact and "on the edge" is certain.
#include "labs/01_point_in_box/PointInBoxChecks.h"

#include "PointInBoxLevel.h"
#include "PointInPolygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using namespace pointinboxchecks;

const Corners square{{0.f, 0.f}, {10.f, 0.f}, {10.f, 10.f}, {0.f, 10.f}};
// A "C", 30 by 30, open on the right between y = 10 and y = 20.
const Corners cShape{{0.f, 0.f},   {30.f, 0.f},  {30.f, 10.f}, {10.f, 10.f},
                     {10.f, 20.f}, {30.f, 20.f}, {30.f, 30.f}, {0.f, 30.f}};
// A diamond: a ray to the right from its middle's height passes exactly through corners.
const Corners diamond{{10.f, 0.f}, {20.f, 10.f}, {10.f, 20.f}, {0.f, 10.f}};
} // namespace

TEST(Task4PointInPolygon, APointInsideASquareIsInside)
{
    EXPECT_TRUE(isInsidePolygon(square, {5.f, 5.f}));
    EXPECT_TRUE(isInsidePolygon(square, {0.5f, 9.5f}));
}

TEST(Task4PointInPolygon, PointsAroundASquareAreOutside)
{
    EXPECT_FALSE(isInsidePolygon(square, {15.f, 5.f}));  // right
    EXPECT_FALSE(isInsidePolygon(square, {-5.f, 5.f}));  // left: the ray crosses two edges
    EXPECT_FALSE(isInsidePolygon(square, {5.f, -5.f}));  // above
    EXPECT_FALSE(isInsidePolygon(square, {5.f, 15.f}));  // below
    EXPECT_FALSE(isInsidePolygon(square, {15.f, 15.f})); // off a corner
}

TEST(Task4PointInPolygon, TheNotchOfAConcaveShapeIsOutside)
{
    EXPECT_FALSE(isInsidePolygon(cShape, {20.f, 15.f})); // in the notch, inside the C's box
    EXPECT_TRUE(isInsidePolygon(cShape, {20.f, 5.f}));   // the top arm
    EXPECT_TRUE(isInsidePolygon(cShape, {20.f, 25.f}));  // the bottom arm
    EXPECT_TRUE(isInsidePolygon(cShape, {5.f, 15.f}));   // the back, left of the notch
    EXPECT_FALSE(isInsidePolygon(cShape, {-5.f, 15.f})); // left of the C
    EXPECT_FALSE(isInsidePolygon(cShape, {35.f, 15.f})); // right of it
}

TEST(Task4PointInPolygon, EitherWayRoundGivesTheSameAnswer)
{
    EXPECT_FALSE(isInsidePolygon(reversed(cShape), {20.f, 15.f}));
    EXPECT_TRUE(isInsidePolygon(reversed(cShape), {20.f, 5.f}));
    EXPECT_TRUE(isInsidePolygon(reversed(cShape), {5.f, 15.f}));
    EXPECT_TRUE(isInsidePolygon(reversed(square), {5.f, 5.f}));
}

// The edge rule: touching is not colliding.
TEST(Task4PointInPolygon, APointOnAnEdgeIsNotInside)
{
    EXPECT_FALSE(isInsidePolygon(square, {0.f, 5.f}));  // left edge
    EXPECT_FALSE(isInsidePolygon(square, {10.f, 5.f})); // right edge
    EXPECT_FALSE(isInsidePolygon(square, {5.f, 0.f}));  // top edge
    EXPECT_FALSE(isInsidePolygon(square, {5.f, 10.f})); // bottom edge
    EXPECT_FALSE(isInsidePolygon(diamond, {5.f, 5.f})); // a slanted edge
    EXPECT_FALSE(isInsidePolygon(diamond, {15.f, 15.f}));
    EXPECT_TRUE(isInsidePolygon(diamond, {6.f, 6.f}));   // just inside that edge
    EXPECT_FALSE(isInsidePolygon(cShape, {20.f, 10.f})); // the notch's top edge
    EXPECT_FALSE(isInsidePolygon(cShape, {10.f, 15.f})); // the notch's back edge
}

TEST(Task4PointInPolygon, APointOnAnEdgeNextToACornerIsNotInside)
{
    // A sixteenth of a pixel from the top-left corner, on the top edge and on the left one.
    EXPECT_FALSE(isInsidePolygon(square, {0.0625f, 0.f}));
    EXPECT_FALSE(isInsidePolygon(square, {0.f, 0.0625f}));
    EXPECT_FALSE(isInsidePolygon(reversed(square), {0.0625f, 0.f}));
    EXPECT_FALSE(isInsidePolygon(reversed(square), {0.f, 0.0625f}));
}

TEST(Task4PointInPolygon, ACornerIsNotInside)
{
    for (const sf::Vector2f corner : square)
        EXPECT_FALSE(isInsidePolygon(square, corner)) << corner.x << ", " << corner.y;
    for (const sf::Vector2f corner : diamond)
        EXPECT_FALSE(isInsidePolygon(diamond, corner)) << corner.x << ", " << corner.y;
    EXPECT_FALSE(isInsidePolygon(cShape, {10.f, 10.f})); // an inner (concave) corner
}

TEST(Task4PointInPolygon, ARayThroughACornerCountsItOnce)
{
    EXPECT_TRUE(isInsidePolygon(diamond, {10.f, 10.f}));  // the ray passes the right corner
    EXPECT_TRUE(isInsidePolygon(diamond, {1.f, 10.f}));   // the same, from near the left one
    EXPECT_FALSE(isInsidePolygon(diamond, {-5.f, 10.f})); // it passes both side corners
    EXPECT_FALSE(isInsidePolygon(diamond, {25.f, 10.f}));
    // A ray along the C's edges at y = 10 and y = 20.
    EXPECT_TRUE(isInsidePolygon(cShape, {5.f, 10.f}));
    EXPECT_TRUE(isInsidePolygon(cShape, {5.f, 20.f}));
    EXPECT_FALSE(isInsidePolygon(cShape, {-5.f, 10.f}));
    EXPECT_FALSE(isInsidePolygon(cShape, {-5.f, 20.f}));
}

TEST(Task4PointInPolygon, NegativeCoordinatesWorkLikeAnyOther)
{
    const Corners shifted{{-20.f, -20.f}, {-10.f, -20.f}, {-10.f, -10.f}, {-20.f, -10.f}};
    EXPECT_TRUE(isInsidePolygon(shifted, {-15.f, -15.f}));
    EXPECT_FALSE(isInsidePolygon(shifted, {-5.f, -15.f}));
    EXPECT_FALSE(isInsidePolygon(shifted, {-25.f, -15.f}));
    EXPECT_FALSE(isInsidePolygon(shifted, {-20.f, -15.f}));
}

TEST(Task4PointInPolygon, FewerThanThreeCornersAreNeverInside)
{
    EXPECT_FALSE(isInsidePolygon({}, {0.f, 0.f}));
    EXPECT_FALSE(isInsidePolygon({{3.f, 3.f}}, {3.f, 3.f}));
    EXPECT_FALSE(isInsidePolygon({{0.f, 0.f}, {10.f, 10.f}}, {5.f, 5.f}));
    EXPECT_FALSE(isInsidePolygon({{0.f, 0.f}, {10.f, 10.f}}, {2.f, 5.f}));
}

// The star the level draws: its middle and its points are inside, the gaps between the
// points (inside the star's bounding box) are not.
TEST(Task4PointInPolygon, TheLevelsStarHasGapsBetweenItsPoints)
{
    const PointInBoxLevel level;
    const Corners& star = level.getStar();
    ASSERT_EQ(star.size(), 10u);
    const sf::Vector2f middle = middleOf(star);
    EXPECT_TRUE(isInsidePolygon(star, middle));
    for (std::size_t corner = 0; corner < star.size(); ++corner)
    {
        // Halfway from the middle to an outer point: inside; just past an inner corner
        // (the gap between two points): outside.
        const sf::Vector2f towards = middle + (star[corner] - middle) * 0.5f;
        const sf::Vector2f beyond = middle + (star[corner] - middle) * 1.3f;
        if (corner % 2 == 0)
            EXPECT_TRUE(isInsidePolygon(star, towards)) << "towards point " << corner;
        else
            EXPECT_FALSE(isInsidePolygon(star, beyond)) << "past inner corner " << corner;
    }
}
