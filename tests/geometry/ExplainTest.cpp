// explain*: the words say what the test compared, and always agree with the test itself.
#include "hitbox/geometry/Explain.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace hitbox;

namespace
{
bool mentions(const Explanation& why, const std::string& text)
{
    return toText(why).find(text) != std::string::npos;
}
} // namespace

TEST(Explain, BoxesThatOnlyTouchSaySoOnTheirAxis)
{
    const Explanation why = explainBoxes({10.f, 0.f, 20.f, 20.f}, {30.f, 5.f, 20.f, 35.f});
    EXPECT_FALSE(why.collides);
    ASSERT_EQ(why.steps.size(), 2u);
    EXPECT_EQ(why.steps[0],
              "x: A [10, 30] and B [30, 50] only touch \xE2\x80\x94 touching is not a "
              "collision");
    EXPECT_EQ(why.steps[1], "y: A [0, 20] and B [5, 40] overlap by 15");
    EXPECT_EQ(why.verdict, "A and B do not collide: on x they only touch");
}

TEST(Explain, BoxesApartAndOverlappingGiveTheGapAndTheDepth)
{
    const Explanation apart =
        explainBoxes({0.f, 0.f, 10.f, 10.f}, {5.f, 30.f, 10.f, 10.f}, "ball", "paddle");
    EXPECT_EQ(apart.steps[1], "y: ball [0, 10] and paddle [30, 40] are 20 apart");
    EXPECT_EQ(apart.verdict, "ball and paddle do not collide: on y they are apart");
    const Explanation hit = explainBoxes({0.f, 0.f, 10.f, 10.f}, {5.f, 5.f, 10.f, 10.f});
    EXPECT_TRUE(hit.collides);
    EXPECT_EQ(hit.verdict, "A and B collide: they overlap on x and on y");
}

TEST(Explain, CirclesCompareSquaredDistanceWithTheSquaredRadiusSum)
{
    const Explanation touching = explainCircles({{0.f, 0.f}, 3.f}, {{3.f, 4.f}, 2.f});
    EXPECT_FALSE(touching.collides);
    EXPECT_TRUE(mentions(touching, "squared distance -3\xC2\xB2 + -4\xC2\xB2 = 25"));
    EXPECT_TRUE(mentions(touching, "radius sum 3 + 2 = 5, squared 25"));
    EXPECT_EQ(touching.verdict, "A and B do not collide: they only touch (25 = 25)");
    const Explanation hit = explainCircles({{0.f, 0.f}, 3.f}, {{3.f, 4.f}, 3.f});
    EXPECT_EQ(hit.verdict, "A and B collide: squared distance 25 < 36");
}

TEST(Explain, CircleAndBoxNameTheNearestPoint)
{
    const Explanation why = explainCircleBox({{-5.f, 5.f}, 4.f}, {0.f, 0.f, 10.f, 10.f});
    EXPECT_FALSE(why.collides);
    EXPECT_TRUE(mentions(why, "is (0, 5)"));
    EXPECT_EQ(why.verdict, "A and B do not collide: squared distance 25 > 16");
}

TEST(Explain, PolygonsListEveryAxisWithBothShadowsAndTheSeparatingOne)
{
    const Polygon a = toPolygon(Box(0.f, 0.f, 10.f, 10.f));
    const Polygon b{{{20.f, 0.f}, {30.f, 10.f}, {20.f, 20.f}}};
    const Explanation why = explainPolygons(a, b);
    EXPECT_FALSE(why.collides);
    EXPECT_EQ(why.steps.size(), 7u) << toText(why); // 4 edges of the square, 3 of the triangle
    EXPECT_TRUE(mentions(why, "A's shadow [0, 10] and B's shadow [20, 30] are 10 apart"))
        << toText(why);
    EXPECT_TRUE(mentions(why, "separates them"));
}

TEST(Explain, SweepsGiveEntryAndExitTimesPerAxis)
{
    const Explanation why =
        explainSweep({0.f, 0.f, 10.f, 10.f}, {40.f, 0.f}, {20.f, 0.f, 10.f, 10.f});
    EXPECT_TRUE(why.collides);
    EXPECT_EQ(why.steps[0], "x: A [0, 10] moving +40 against B [20, 30]: overlaps from t = 0.25 to "
                            "t = 0.75");
    EXPECT_EQ(why.verdict, "A hits B at t = 0.25, on its x side");
    const Explanation late =
        explainSweep({0.f, 0.f, 10.f, 10.f}, {5.f, 0.f}, {20.f, 0.f, 10.f, 10.f});
    EXPECT_EQ(late.verdict, "A misses B: they would meet at t = 2, after the move ends");
}

TEST(Explain, AlwaysAgreesWithTheTestsOverManyWholeNumberCases)
{
    // Whole numbers in a small range meet the edges (touching, zero sizes) often.
    std::mt19937 random(25);
    std::uniform_int_distribution<int> coordinate(-6, 6);
    const auto value = [&] { return static_cast<float>(coordinate(random)); };
    for (int i = 0; i < 5000; ++i)
    {
        const Box a(value(), value(), value(), value());
        const Box b(value(), value(), value(), value());
        const Circle c{{value(), value()}, std::fabs(value())};
        const Circle d{{value(), value()}, std::fabs(value())};
        const Vec2 move(value() * 3.f, value() * 3.f);
        ASSERT_EQ(explainBoxes(a, b).collides, boxVsBox(a, b));
        ASSERT_EQ(explainCircles(c, d).collides, circleVsCircle(c, d));
        ASSERT_EQ(explainCircleBox(c, a).collides, circleVsBox(c, a));
        ASSERT_EQ(explainSweep(a, move, b).collides, sweepBoxVsBox(a, move, b).hit);
        // The verdict never contradicts the answer.
        const Explanation why = explainPolygons(toPolygon(a), toPolygon(b));
        ASSERT_EQ(why.verdict.find("do not collide") == std::string::npos, why.collides)
            << toText(why);
        ASSERT_EQ(explainBoxes(a, b).verdict.find("do not collide") == std::string::npos,
                  boxVsBox(a, b));
    }
}
