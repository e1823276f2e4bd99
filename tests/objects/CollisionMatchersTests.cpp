// The matchers of support/CollisionMatchers.h: each passes and fails when it should, and a
// failure carries explain's words.
#include "support/CollisionMatchers.h"

#include <gtest/gtest.h>

#include <string>

using namespace hitbox::testing;
using ::testing::Not;

namespace
{

hitbox::GameObject square(const char* name, float x, float y, float side = 10.f)
{
    hitbox::GameObject object;
    object.setName(name);
    object.setSize({side, side});
    object.setPosition({x, y});
    return object;
}

// What a matcher says when `value` fails it.
template <typename Value, typename MatcherType>
std::string failureText(const Value& value, const MatcherType& matcher)
{
    ::testing::StringMatchResultListener listener;
    EXPECT_FALSE(::testing::ExplainMatchResult(matcher, value, &listener));
    return listener.str();
}

} // namespace

TEST(CollisionMatchers, CollidesAndNotCollidesFollowTheEdgeRule)
{
    const hitbox::GameObject ball = square("ball", 0.f, 0.f);
    const hitbox::GameObject overlapping = square("paddle", 5.f, 5.f);
    const hitbox::GameObject touching = square("wall", 10.f, 0.f);
    EXPECT_THAT(ball, Collides(overlapping));
    EXPECT_THAT(ball, NotCollides(touching));
    EXPECT_THAT(ball, Not(Collides(touching)));
    EXPECT_THAT(ball, Touches(touching));
    EXPECT_THAT(ball, Not(Touches(overlapping)));
}

TEST(CollisionMatchers, AFailureSaysWhyInExplainsWords)
{
    const hitbox::GameObject ball = square("ball", 0.f, 0.f);
    const hitbox::GameObject wall = square("wall", 10.f, 0.f);
    const std::string text = failureText(ball, Collides(wall));
    EXPECT_NE(text.find("x: 'ball' [0, 10] and 'wall' [10, 20] only touch"), std::string::npos)
        << text;
}

TEST(CollisionMatchers, CirclesUseTheBoundingCircles)
{
    const hitbox::GameObject a = square("a", 0.f, 0.f);
    const hitbox::GameObject b = square("b", 9.f, 9.f); // boxes overlap by 1, circles are apart
    EXPECT_THAT(a, Collides(b));
    EXPECT_THAT(a, NotCollides(b, Shape::Circle, Shape::Circle));
}

TEST(CollisionMatchers, HitsAtAndHasNormalReadTheSweep)
{
    const SweepCase bullet =
        sweep(hitbox::Box(0.f, 0.f, 10.f, 10.f), {40.f, 0.f}, hitbox::Box(20.f, 0.f, 10.f, 10.f));
    EXPECT_THAT(bullet, HitsAt(0.25f, 1e-6f));
    EXPECT_THAT(bullet, Not(HitsAt(0.5f, 0.1f)));
    const std::string text = failureText(bullet, HitsAt(0.5f, 0.1f));
    EXPECT_NE(text.find("overlaps from t = 0.25 to t = 0.75"), std::string::npos) << text;
    const hitbox::Hit hit = hitbox::sweepBoxVsBox(bullet.mover, bullet.move, bullet.target);
    EXPECT_THAT(hit, HasNormal(hitbox::Vec2(-1.f, 0.f)));
    EXPECT_THAT(hit, Not(HasNormal(hitbox::Vec2(0.f, 1.f))));
}

TEST(CollisionMatchers, StaysInsideNamesTheEdgeThatLeft)
{
    const hitbox::GameObject player = square("player", 95.f, 10.f);
    EXPECT_THAT(player, StaysInside(hitbox::Box(0.f, 0.f, 105.f, 100.f))) << "touching is inside";
    const std::string text = failureText(player, StaysInside(hitbox::Box(0.f, 0.f, 100.f, 100.f)));
    EXPECT_EQ(text, "its right edge 105 is past the area's 100");
}

TEST(CollisionMatchers, WorkOnALabsOwnObjectClasses)
{
    struct Ball : hitbox::GameObject
    {
        int bounces = 0;
    };
    Ball ball;
    ball.setSize({10.f, 10.f});
    const hitbox::GameObject wall = square("wall", 5.f, 0.f);
    EXPECT_THAT(ball, Collides(wall));
}
