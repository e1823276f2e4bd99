// --timeline (Timeline.h): every contact event a level reports, with the step it happened in,
// written as CSV by the one writer (Csv.h), and kept by a TimelineLevel around any level.
#include "hitbox/app/App.h"
#include "hitbox/app/ReplayLevel.h"
#include "hitbox/app/Timeline.h"
#include "hitbox/objects/GameObject.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{

// Two named objects that meet on step 2, stay on step 3 and part on step 4; then the second
// is destroyed (an Exit with no object) on step 6 after meeting again on step 5.
class MeetingLevel : public hitbox::Level
{
public:
    MeetingLevel()
    {
        first.setName("ball");
        second.setName("wall, left");
    }
    void update(float) override
    {
        ++steps;
        events.clear();
        const auto event = [this](hitbox::ContactPhase phase, hitbox::GameObject* other)
        {
            hitbox::PairEvent pair;
            pair.phase = phase;
            pair.first = &first;
            pair.second = other;
            pair.contact.hit = true;
            pair.contact.normal = {-1.f, 0.f};
            pair.contact.depth = 0.25f;
            return pair;
        };
        if (steps == 2 || steps == 5)
            events.push_back(event(hitbox::ContactPhase::Enter, &second));
        if (steps == 3)
            events.push_back(event(hitbox::ContactPhase::Stay, &second));
        if (steps == 4)
            events.push_back(event(hitbox::ContactPhase::Exit, &second));
        if (steps == 6)
            events.push_back(event(hitbox::ContactPhase::Exit, nullptr));
    }
    void render(sf::RenderTarget&) const override {}
    std::vector<hitbox::PairEvent> getContactEvents() const override { return events; }

    hitbox::GameObject first;
    hitbox::GameObject second;
    int steps = 0;
    std::vector<hitbox::PairEvent> events;
};

} // namespace

TEST(Timeline, KeepsEveryEventWithItsStepAndWritesOneCsvRowEach)
{
    MeetingLevel level;
    hitbox::TimelineLevel timeline(level);
    hitbox::simulate(timeline, 8);
    const std::vector<hitbox::TimelineEvent>& events = timeline.getTimeline().getEvents();
    ASSERT_EQ(events.size(), 5u);
    EXPECT_EQ(events[0].step, 2);
    EXPECT_EQ(events[0].kind, hitbox::ContactPhase::Enter);
    EXPECT_EQ(events[2].step, 4);
    EXPECT_EQ(events[2].kind, hitbox::ContactPhase::Exit);
    EXPECT_EQ(events[4].b, "(destroyed)");

    const std::string csv = hitbox::timelineCsv(events);
    EXPECT_EQ(csv.substr(0, csv.find("\r\n", csv.find("\r\n") + 2) + 2),
              "step,time,a,b,kind,normal_x,normal_y,depth,trigger\r\n"
              "2,0.0166666675,ball,\"wall, left\",enter,-1,0,0.25,no\r\n");
    EXPECT_NE(csv.find("\r\n6,0.0500000007,ball,(destroyed),exit,-1,0,0.25,no\r\n"),
              std::string::npos)
        << csv;
}

TEST(Timeline, DropAfterForgetsOnlyTheLaterSteps)
{
    MeetingLevel level;
    hitbox::TimelineLevel timeline(level);
    hitbox::simulate(timeline, 8);
    hitbox::Timeline copy = timeline.getTimeline();
    copy.dropAfter(4);
    ASSERT_EQ(copy.getEvents().size(), 3u);
    EXPECT_EQ(copy.getEvents().back().step, 4);
    copy.dropAfter(0);
    EXPECT_TRUE(copy.getEvents().empty());
}
