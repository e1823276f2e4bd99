// PushOutTest.cpp - after pushOutOffset the pair does not collide: every shape pair with a
// contact test, 10^6 seeded whole-number cases each, at three scales (shapes near the origin,
// a few screens, and out to the edge of Range.h's exact range). Label `long` (issue 25,
// item 2: before, 8 % to 47 % of such cases still collided by about 1e-6 px).
#include "hitbox/geometry/Capsule.h"
#include "hitbox/geometry/Overlap.h"
#include "hitbox/geometry/Polygon.h"
#include "hitbox/geometry/Response.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>

namespace
{
constexpr int casesPerPair = 1'000'000;

// Whole-number shapes around `range` px from the origin, sizes up to a tenth of it (+30).
struct CaseMaker
{
    explicit CaseMaker(float range) : range(range) {}
    float whole(float lowest, float highest)
    {
        return static_cast<float>(std::uniform_int_distribution<long long>(
            static_cast<long long>(lowest), static_cast<long long>(highest))(random));
    }
    hitbox::Vec2 centre() { return {whole(-range, range), whole(-range, range)}; }
    hitbox::Vec2 near(hitbox::Vec2 other)
    {
        const float spread = range / 10.f + 40.f;
        return {other.x + whole(-spread, spread), other.y + whole(-spread, spread)};
    }
    float size() { return whole(1.f, range / 10.f + 30.f); }
    hitbox::Vec2 halfSize() { return {size(), size()}; }
    float angle() { return whole(0.f, 359.f); }
    hitbox::Capsule capsule(hitbox::Vec2 start)
    {
        return {start, {start.x + whole(-40.f, 40.f), start.y + whole(-40.f, 40.f)}, size()};
    }

    float range;
    std::mt19937_64 random{25};
};

// One case: the contact of A and B, and the contact after A moved by an offset.
struct PushCase
{
    hitbox::Contact before;
    std::function<hitbox::Contact(hitbox::Vec2)> after;
};

void expectEveryPushSeparates(const std::string& pair, float range,
                              const std::function<PushCase(CaseMaker&)>& make)
{
    CaseMaker maker(range);
    int hits = 0;
    int stillColliding = 0;
    std::string first;
    for (int index = 0; index < casesPerPair; ++index)
    {
        const PushCase one = make(maker);
        if (!one.before.hit)
            continue;
        ++hits;
        const hitbox::Contact after = one.after(hitbox::pushOutOffset(one.before));
        if (after.hit && ++stillColliding == 1)
            first = "case " + std::to_string(index) + ": still " + std::to_string(after.depth) +
                    " px inside";
    }
    EXPECT_GT(hits, casesPerPair / 10) << pair << ": too few cases collide to prove anything";
    EXPECT_EQ(stillColliding, 0) << pair << " at +-" << range << " px: " << stillColliding << " of "
                                 << hits << " pushes left the pair colliding; " << first;
}

void everyPair(float range)
{
    using hitbox::Vec2;
    expectEveryPushSeparates(
        "circle-circle", range,
        [](CaseMaker& m)
        {
            const hitbox::Circle a{m.centre(), m.size()};
            const hitbox::Circle b{m.near(a.center), m.size()};
            return PushCase{hitbox::circleVsCircleContact(a, b), [=](Vec2 o) {
                                return hitbox::circleVsCircleContact({a.center + o, a.radius}, b);
                            }};
        });
    expectEveryPushSeparates(
        "circle-box", range,
        [](CaseMaker& m)
        {
            const hitbox::Circle a{m.centre(), m.size()};
            const Vec2 corner = m.near(a.center);
            const hitbox::Box b(corner.x, corner.y, m.size(), m.size());
            return PushCase{hitbox::circleVsBoxContact(a, b), [=](Vec2 o) {
                                return hitbox::circleVsBoxContact({a.center + o, a.radius}, b);
                            }};
        });
    expectEveryPushSeparates("box-box", range,
                             [](CaseMaker& m)
                             {
                                 const Vec2 corner = m.centre();
                                 const hitbox::Box a(corner.x, corner.y, m.size(), m.size());
                                 const Vec2 other = m.near(corner);
                                 const hitbox::Box b(other.x, other.y, m.size(), m.size());
                                 return PushCase{
                                     hitbox::boxVsBoxContact(a, b), [=](Vec2 o) {
                                         return hitbox::boxVsBoxContact(
                                             {a.left + o.x, a.top + o.y, a.width, a.height}, b);
                                     }};
                             });
    expectEveryPushSeparates(
        "orientedbox-orientedbox", range,
        [](CaseMaker& m)
        {
            const hitbox::OrientedBox a{m.centre(), m.halfSize(), m.angle()};
            const hitbox::OrientedBox b{m.near(a.center), m.halfSize(), m.angle()};
            return PushCase{hitbox::orientedBoxVsOrientedBox(a, b), [=](Vec2 o) {
                                return hitbox::orientedBoxVsOrientedBox(
                                    {a.center + o, a.halfSize, a.angleDegrees}, b);
                            }};
        });
    expectEveryPushSeparates(
        "circle-polygon", range,
        [](CaseMaker& m)
        {
            const hitbox::Circle a{m.centre(), m.size()};
            const hitbox::Polygon b =
                hitbox::toPolygon(hitbox::OrientedBox{m.near(a.center), m.halfSize(), m.angle()});
            return PushCase{hitbox::circleVsPolygon(a, b), [=](Vec2 o) {
                                return hitbox::circleVsPolygon({a.center + o, a.radius}, b);
                            }};
        });
    expectEveryPushSeparates(
        "capsule-circle", range,
        [](CaseMaker& m)
        {
            const hitbox::Capsule a = m.capsule(m.centre());
            const hitbox::Circle b{m.near(a.start), m.size()};
            return PushCase{
                hitbox::capsuleVsCircle(a, b), [=](Vec2 o) {
                    return hitbox::capsuleVsCircle({a.start + o, a.end + o, a.radius}, b);
                }};
        });
    expectEveryPushSeparates(
        "capsule-capsule", range,
        [](CaseMaker& m)
        {
            const hitbox::Capsule a = m.capsule(m.centre());
            const hitbox::Capsule b = m.capsule(m.near(a.start));
            return PushCase{
                hitbox::capsuleVsCapsule(a, b), [=](Vec2 o) {
                    return hitbox::capsuleVsCapsule({a.start + o, a.end + o, a.radius}, b);
                }};
        });
    expectEveryPushSeparates(
        "capsule-polygon", range,
        [](CaseMaker& m)
        {
            const hitbox::Capsule a = m.capsule(m.centre());
            const hitbox::Polygon b =
                hitbox::toPolygon(hitbox::OrientedBox{m.near(a.start), m.halfSize(), m.angle()});
            return PushCase{
                hitbox::capsuleVsPolygon(a, b), [=](Vec2 o) {
                    return hitbox::capsuleVsPolygon({a.start + o, a.end + o, a.radius}, b);
                }};
        });
}
} // namespace

TEST(PushOutSeparates, EveryPairNearTheOrigin)
{
    everyPair(50.f);
}

TEST(PushOutSeparates, EveryPairAcrossAFewScreens)
{
    everyPair(1000.f);
}

TEST(PushOutSeparates, EveryPairOutToTheEdgeOfTheExactRange)
{
    everyPair(900'000.f);
}
