// Contact events (issue 27, item 1): enter the first step a pair collides, stay every further
// step, exit the first step it does not - also when one of the two is removed, destroyed,
// killed or stops being a collider. Checked over every scripted sequence of four steps.
#include "hitbox/objects/ExplainPair.h"
#include "hitbox/objects/GameObject.h"
#include "hitbox/objects/World.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

using hitbox::BroadphaseMethod;
using hitbox::CollisionEvent;
using hitbox::ContactPhase;
using hitbox::World;

namespace
{

const BroadphaseMethod allMethods[] = {BroadphaseMethod::BruteForce, BroadphaseMethod::SortAndSweep,
                                       BroadphaseMethod::Grid, BroadphaseMethod::Quadtree};

struct Heard
{
    ContactPhase phase;
    const hitbox::GameObject* other;
    int step; // the test's own step counter
    bool operator==(const Heard& x) const
    {
        return phase == x.phase && other == x.other && step == x.step;
    }
};

std::ostream& operator<<(std::ostream& out, const Heard& heard)
{
    return out << hitbox::toString(heard.phase) << "@" << heard.step;
}

// A square that writes down every event it hears, stamped with the test's step.
class Listener : public hitbox::GameObject
{
public:
    explicit Listener(float x, float side = 20.f)
    {
        setSize({side, side});
        setPosition({x, 0.f});
    }
    void onCollisionEnter(const CollisionEvent& event) override { note(event); }
    void onCollisionStay(const CollisionEvent& event) override { note(event); }
    void onCollisionExit(const CollisionEvent& event) override { note(event); }
    void note(const CollisionEvent& event)
    {
        heard.push_back({event.phase, event.other, *stepNow});
        contacts.push_back(event.contact);
    }
    std::vector<Heard> heard;
    std::vector<hitbox::Contact> contacts;
    const int* stepNow = nullptr;
};

// What the second square does in one scripted step.
enum class State
{
    Overlapping,
    Apart,
    Touching, // edges meet exactly: not a collision
    Dead,
    NotCollider,
    Removed // out of the World for this step (added back when the script says so)
};
const State allStates[] = {State::Overlapping, State::Apart,       State::Touching,
                           State::Dead,        State::NotCollider, State::Removed};

} // namespace

TEST(WorldEvents, EveryScriptedSequenceOfFourStepsGivesEnterStayExitInOrder)
{
    // 6^4 scripts of the second square's state, for every broadphase: the events both
    // squares hear follow from "did they collide last step, and this step?" alone.
    const int steps = 4;
    int scripts = 0;
    for (BroadphaseMethod method : allMethods)
    {
        for (int code = 0; code < 6 * 6 * 6 * 6; ++code)
        {
            std::vector<State> script;
            for (int s = 0, rest = code; s < steps; ++s, rest /= 6)
                script.push_back(allStates[rest % 6]);
            int stepNow = 0;
            Listener a(0.f), b(100.f);
            a.stepNow = &stepNow;
            b.stepNow = &stepNow;
            World world(method);
            world.add(a);
            world.add(b);
            std::vector<Heard> expectA, expectB;
            bool before = false;
            for (stepNow = 0; stepNow < steps; ++stepNow)
            {
                const State state = script[static_cast<std::size_t>(stepNow)];
                b.setPosition({state == State::Overlapping ? 10.f
                               : state == State::Touching  ? 20.f
                                                           : 100.f,
                               0.f});
                b.setAlive(state != State::Dead);
                b.setCollider(state != State::NotCollider);
                if (state == State::Removed)
                    world.remove(b);
                else
                    world.add(b);
                const bool now = state == State::Overlapping;
                if (now || before)
                {
                    const ContactPhase phase = !before ? ContactPhase::Enter
                                               : now   ? ContactPhase::Stay
                                                       : ContactPhase::Exit;
                    expectA.push_back({phase, &b, stepNow});
                    expectB.push_back({phase, &a, stepNow});
                }
                world.checkCollisions();
                before = now;
            }
            ASSERT_EQ(a.heard, expectA) << "script " << code << ", method " << int(method);
            ASSERT_EQ(b.heard, expectB) << "script " << code << ", method " << int(method);
            ++scripts;
        }
    }
    EXPECT_EQ(scripts, 4 * 1296);
}

TEST(WorldEvents, EventsCarryTheContactSeenFromEachObject)
{
    int step = 0;
    Listener a(0.f), b(15.f); // b overlaps a's right side by 5 px
    a.stepNow = b.stepNow = &step;
    World world;
    world.add(a);
    world.add(b);
    world.checkCollisions();
    ASSERT_EQ(a.contacts.size(), 1u);
    EXPECT_EQ(a.contacts[0].normal, hitbox::Vec2(-1.f, 0.f)) << "out of b towards a";
    EXPECT_EQ(b.contacts[0].normal, hitbox::Vec2(1.f, 0.f)) << "out of a towards b";
    EXPECT_FLOAT_EQ(a.contacts[0].depth, 5.f);
    EXPECT_FLOAT_EQ(b.contacts[0].depth, 5.f);
    ASSERT_EQ(world.getEvents().size(), 1u);
    EXPECT_EQ(world.getEvents()[0].phase, ContactPhase::Enter);
    EXPECT_EQ(world.getEvents()[0].first, &a);
}

TEST(WorldEvents, AnObjectDestroyedGivesItsPartnerAnExitWithNoOther)
{
    int step = 0;
    Listener a(0.f);
    a.stepNow = &step;
    World world;
    world.add(a);
    {
        Listener b(10.f);
        b.stepNow = &step;
        world.add(b);
        world.checkCollisions();
    }
    ASSERT_EQ(a.heard.size(), 2u);
    EXPECT_EQ(a.heard[1].phase, ContactPhase::Exit);
    EXPECT_EQ(a.heard[1].other, nullptr) << "the other object no longer exists";
}

TEST(WorldEvents, AnObjectRemovedMidPassGetsItsExitAtTheEndOfThePass)
{
    int step = 0;
    Listener a(0.f), b(10.f);
    a.stepNow = b.stepNow = &step;
    World world;
    world.add(a);
    world.add(b);
    world.checkCollisions();
    struct Remover : Listener
    {
        using Listener::Listener;
        void collisionResponse(hitbox::GameObject* other) override
        {
            if (other != nullptr)
                world->remove(*other);
        }
        World* world = nullptr;
    } c(5.f);
    c.stepNow = &step;
    c.world = &world;
    world.add(c);
    step = 1;
    world.checkCollisions(); // (a, b) stays; then (a, c): c removes a; (b, c) still runs
    std::vector<Heard> expectA = {{ContactPhase::Enter, &b, 0},
                                  {ContactPhase::Stay, &b, 1},
                                  {ContactPhase::Enter, &c, 1},
                                  {ContactPhase::Exit, &b, 1},
                                  {ContactPhase::Exit, &c, 1}};
    EXPECT_EQ(a.heard, expectA);
    EXPECT_FALSE(world.contains(a));
}

TEST(WorldEvents, ClearGivesEveryPairItsExit)
{
    int step = 0;
    Listener a(0.f), b(10.f);
    a.stepNow = b.stepNow = &step;
    World world;
    world.add(a);
    world.add(b);
    world.checkCollisions();
    world.clear();
    ASSERT_EQ(a.heard.size(), 2u);
    EXPECT_EQ(a.heard[1].phase, ContactPhase::Exit);
    EXPECT_EQ(b.heard[1].phase, ContactPhase::Exit);
}

TEST(WorldEvents, TriggersReportButAreNeverPushedSolidsAre)
{
    hitbox::GameObject wall, player, sensor;
    wall.setSize({100.f, 100.f});
    player.setSize({20.f, 20.f});
    player.setPosition({90.f, 40.f}); // 10 px into the wall's right side
    sensor.setSize({20.f, 20.f});
    sensor.setPosition({85.f, 10.f});
    World world;
    world.setPushApart(true);
    world.add(wall, 1, 0xFFFFFFFF, World::Shape::Box, World::Body::Fixed);
    world.add(player);
    world.add(sensor, 1, 0xFFFFFFFF, World::Shape::Box, World::Body::Trigger);
    world.checkCollisions();
    EXPECT_EQ(wall.getPosition(), sf::Vector2f(0.f, 0.f)) << "a Fixed body never moves";
    EXPECT_EQ(player.getPosition(), sf::Vector2f(100.f, 40.f)) << "pushed out of the wall";
    EXPECT_EQ(sensor.getPosition(), sf::Vector2f(85.f, 10.f)) << "a trigger is never pushed";
    int triggerEvents = 0;
    for (const hitbox::PairEvent& event : world.getEvents())
        triggerEvents += event.trigger ? 1 : 0;
    EXPECT_EQ(triggerEvents, 1) << "the sensor reports its overlap with the wall";
}

TEST(WorldEvents, AHundredThousandObjectsEachEnterOnceAndExitOnce)
{
    // 50,000 pairs side by side, each pair overlapping: one enter per pair; moved apart: one
    // exit per pair; nothing else.
    const std::size_t pairs = 50000;
    std::vector<hitbox::GameObject> objects(2 * pairs);
    World world;
    for (std::size_t i = 0; i < pairs; ++i)
    {
        const float x = 40.f * static_cast<float>(i % 1000);
        const float y = 40.f * static_cast<float>(i / 1000);
        objects[2 * i].setSize({10.f, 10.f});
        objects[2 * i].setPosition({x, y});
        objects[2 * i + 1].setSize({10.f, 10.f});
        objects[2 * i + 1].setPosition({x + 5.f, y});
        world.add(objects[2 * i]);
        world.add(objects[2 * i + 1]);
    }
    world.checkCollisions();
    EXPECT_EQ(world.getEvents().size(), pairs);
    for (const hitbox::PairEvent& event : world.getEvents())
        ASSERT_EQ(event.phase, ContactPhase::Enter);
    world.checkCollisions();
    EXPECT_EQ(world.getEvents().size(), pairs);
    for (const hitbox::PairEvent& event : world.getEvents())
        ASSERT_EQ(event.phase, ContactPhase::Stay);
    for (std::size_t i = 0; i < pairs; ++i)
        objects[2 * i + 1].move({10.f, 0.f}); // now only touching
    world.checkCollisions();
    EXPECT_EQ(world.getEvents().size(), pairs);
    for (const hitbox::PairEvent& event : world.getEvents())
        ASSERT_EQ(event.phase, ContactPhase::Exit);
    world.checkCollisions();
    EXPECT_TRUE(world.getEvents().empty());
}

TEST(ExplainPair, NamesTheObjectsAndSaysWhyDeadOrNotColliderObjectsNeverCollide)
{
    hitbox::GameObject ball, paddle;
    ball.setName("ball");
    paddle.setName("paddle");
    ball.setSize({10.f, 10.f});
    paddle.setSize({20.f, 80.f});
    ball.setPosition({100.f, 40.f});
    paddle.setPosition({95.f, 60.f});
    const hitbox::Explanation apart = hitbox::explain(ball, paddle);
    EXPECT_FALSE(apart.collides);
    EXPECT_EQ(apart.verdict, "'ball' and 'paddle' do not collide: on y they are apart");
    EXPECT_EQ(apart.steps[1], "y: 'ball' [40, 50] and 'paddle' [60, 140] are 10 apart");
    ball.setPosition({100.f, 65.f});
    EXPECT_TRUE(hitbox::explain(ball, paddle).collides);
    paddle.setCollider(false);
    EXPECT_EQ(
        hitbox::explain(ball, paddle).verdict,
        "'ball' and 'paddle' do not collide: 'paddle' is not a collider (setCollider(false))");
    EXPECT_FALSE(hitbox::explain(ball, paddle).collides);
}
