// CollisionMatchers.h - GoogleTest matchers for collision tests, for students and graders:
//
//     EXPECT_THAT(ball, Collides(paddle));
//     EXPECT_THAT(coin, NotCollides(player));
//     EXPECT_THAT(player, Touches(wall));                 // edges meet, no shared area
//     EXPECT_THAT(sweep(bullet, move, wall), HitsAt(0.25f, 0.001f));
//     EXPECT_THAT(contact, HasNormal({-1.f, 0.f}));
//     EXPECT_THAT(player, StaysInside(screen));
//
// A failure says why in explain's words (hitbox/objects/ExplainPair.h), e.g.
//     Value of: ball
//     Expected: collides with 'paddle'
//       Actual: 'ball', collision box x [100, 110], y [40, 50] (of type GameObject), which
//       does not: 'ball' and 'paddle' do not collide: on y they are apart
//         x: 'ball' [100, 110] and 'paddle' [95, 115] overlap by 10
//         y: 'ball' [40, 50] and 'paddle' [60, 80] are 10 apart
// Test code only (tests/ links GoogleTest's gmock): never include it in a program.
#pragma once

#include "hitbox/geometry/Explain.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Sweep.h"
#include "hitbox/objects/ExplainPair.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/objects/World.h"
#include "hitbox/sfml/Conversions.h"

#include <gmock/gmock.h>

#include <cmath>
#include <ostream>
#include <string>

// How a GameObject shows in a failure: its name (or position) and its collision box.
inline std::ostream& operator<<(std::ostream& out, const hitbox::GameObject& object)
{
    const hitbox::Box box = hitbox::normalised(hitbox::toBox(object.getCollisionBox()));
    return out << object.describe() << ", collision box x [" << box.left << ", "
               << box.left + box.width << "], y [" << box.top << ", " << box.top + box.height
               << "]";
}

namespace hitbox::testing
{

using Shape = World::Shape;

// A box's straight move against a still box, for HitsAt (sweepBoxVsBox's arguments).
struct SweepCase
{
    Box mover;
    Vec2 move;
    Box target;
};
inline SweepCase sweep(const Box& mover, Vec2 move, const Box& target)
{
    return {mover, move, target};
}
inline SweepCase sweep(const hitbox::GameObject& mover, Vec2 move, const hitbox::GameObject& target)
{
    return {toBox(mover.getCollisionBox()), move, toBox(target.getCollisionBox())};
}
inline std::ostream& operator<<(std::ostream& out, const SweepCase& sweepCase)
{
    return out << "a sweep by (" << sweepCase.move.x << ", " << sweepCase.move.y << ")";
}

// Collides / NotCollides: the World's exact test for the two shapes (Box: the collision box,
// Circle: the bounding circle); touching is not colliding.
class CollidesMatcher : public ::testing::MatcherInterface<const hitbox::GameObject&>
{
public:
    CollidesMatcher(const hitbox::GameObject& other, bool wanted, Shape shape, Shape otherShape)
        : other(other), wanted(wanted), shape(shape), otherShape(otherShape)
    {
    }
    bool MatchAndExplain(const hitbox::GameObject& object,
                         ::testing::MatchResultListener* listener) const override
    {
        const Explanation why = explain(object, other, shape, otherShape);
        *listener << (why.collides ? "which does: " : "which does not: ") << toText(why);
        return why.collides == wanted;
    }
    void DescribeTo(std::ostream* out) const override
    {
        *out << (wanted ? "collides with " : "does not collide with ") << other.describe();
    }
    void DescribeNegationTo(std::ostream* out) const override
    {
        *out << (wanted ? "does not collide with " : "collides with ") << other.describe();
    }

private:
    const hitbox::GameObject& other;
    bool wanted;
    Shape shape;
    Shape otherShape;
};

inline ::testing::Matcher<const hitbox::GameObject&>
Collides(const hitbox::GameObject& other, Shape shape = Shape::Box, Shape otherShape = Shape::Box)
{
    return ::testing::MakeMatcher(new CollidesMatcher(other, true, shape, otherShape));
}
inline ::testing::Matcher<const hitbox::GameObject&> NotCollides(const hitbox::GameObject& other,
                                                                 Shape shape = Shape::Box,
                                                                 Shape otherShape = Shape::Box)
{
    return ::testing::MakeMatcher(new CollidesMatcher(other, false, shape, otherShape));
}

// Touches: the collision boxes meet along an edge or at a corner and share no area.
class TouchesMatcher : public ::testing::MatcherInterface<const hitbox::GameObject&>
{
public:
    explicit TouchesMatcher(const hitbox::GameObject& other) : other(other) {}
    bool MatchAndExplain(const hitbox::GameObject& object,
                         ::testing::MatchResultListener* listener) const override
    {
        const Box a = normalised(toBox(object.getCollisionBox()));
        const Box b = normalised(toBox(other.getCollisionBox()));
        // Every span reaches the other's (overlapping or touching), and not all share length.
        const bool reachX = a.left <= b.left + b.width && b.left <= a.left + a.width;
        const bool reachY = a.top <= b.top + b.height && b.top <= a.top + a.height;
        *listener << toText(explain(object, other));
        return reachX && reachY && !boxVsBox(a, b);
    }
    void DescribeTo(std::ostream* out) const override
    {
        *out << "touches " << other.describe() << " (edges meet, no shared area)";
    }

private:
    const hitbox::GameObject& other;
};

inline ::testing::Matcher<const hitbox::GameObject&> Touches(const hitbox::GameObject& other)
{
    return ::testing::MakeMatcher(new TouchesMatcher(other));
}

// HitsAt: the sweep hits at `time` (a fraction of the move) within `tolerance`.
MATCHER_P2(HitsAt, time, tolerance,
           std::string(negation ? "does not hit" : "hits") +
               " at t = " + ::testing::PrintToString(time) + " (within " +
               ::testing::PrintToString(tolerance) + ")")
{
    const Hit hit = sweepBoxVsBox(arg.mover, arg.move, arg.target);
    *result_listener << toText(explainSweep(arg.mover, arg.move, arg.target));
    return hit.hit && std::fabs(hit.time - static_cast<float>(time)) <= tolerance;
}

// HasNormal: a Contact's or Hit's normal is `normal` (within 1e-5 on each axis).
MATCHER_P(HasNormal, normal,
          std::string(negation ? "has no" : "has a") + " normal (" +
              ::testing::PrintToString(normal.x) + ", " + ::testing::PrintToString(normal.y) + ")")
{
    *result_listener << "whose normal is (" << arg.normal.x << ", " << arg.normal.y << ")"
                     << (arg.hit ? "" : ", and there is no hit at all");
    return arg.hit && std::fabs(arg.normal.x - normal.x) <= 1e-5f &&
           std::fabs(arg.normal.y - normal.y) <= 1e-5f;
}

// StaysInside: the collision box is inside `area`; touching its edges counts as inside.
class StaysInsideMatcher : public ::testing::MatcherInterface<const hitbox::GameObject&>
{
public:
    explicit StaysInsideMatcher(const Box& area) : area(normalised(area)) {}
    bool MatchAndExplain(const hitbox::GameObject& object,
                         ::testing::MatchResultListener* listener) const override
    {
        const Box box = normalised(toBox(object.getCollisionBox()));
        bool inside = true;
        const auto check = [&](bool ok, const char* side, float edge, float limit)
        {
            if (ok)
                return;
            *listener << (inside ? "" : "; ") << "its " << side << " edge " << edge
                      << " is past the area's " << limit;
            inside = false;
        };
        check(box.left >= area.left, "left", box.left, area.left);
        check(box.top >= area.top, "top", box.top, area.top);
        check(box.left + box.width <= area.left + area.width, "right", box.left + box.width,
              area.left + area.width);
        check(box.top + box.height <= area.top + area.height, "bottom", box.top + box.height,
              area.top + area.height);
        return inside;
    }
    void DescribeTo(std::ostream* out) const override
    {
        *out << "stays inside x [" << area.left << ", " << area.left + area.width << "], y ["
             << area.top << ", " << area.top + area.height << "]";
    }

private:
    Box area;
};

inline ::testing::Matcher<const hitbox::GameObject&> StaysInside(const Box& area)
{
    return ::testing::MakeMatcher(new StaysInsideMatcher(area));
}

} // namespace hitbox::testing
