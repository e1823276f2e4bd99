// Timeline.h - every contact event of a run (enter, stay, exit: objects/ContactEvent.h), kept
// as plain values with the step it happened in: --timeline FILE.csv writes it, the rewind
// strip draws its enters and exits (debug/TimelineStrip.h).
#pragma once

#include "hitbox/geometry/Vec2.h"
#include "hitbox/objects/ContactEvent.h"

#include <string>
#include <vector>

namespace hitbox
{

// One event, with names rather than pointers (an object may be gone by the time it is read).
struct TimelineEvent
{
    long long step = 0; // fixed steps run when it happened: 1 is the first step (the number
                        // --pause-at-step takes to stop right after it)
    std::string a;      // the pair's first object: its name, else GameObject::describe()
    std::string b;      // "(destroyed)" for an object destroyed before its Exit
    ContactPhase kind = ContactPhase::Enter;
    Vec2 normal;       // out of b towards a; for an Exit, the last contact's
    float depth = 0.f; // > 0 (an Exit: the last depth while they collided)
    bool trigger = false;
};

class Timeline
{
public:
    // Adds the events of step `step` (World::getEvents() after that step's check).
    void addStep(long long step, const std::vector<PairEvent>& events);

    [[nodiscard]] const std::vector<TimelineEvent>& getEvents() const { return events; }

    // Forgets the events after step `step` (a rewind that will simulate them again).
    void dropAfter(long long step);

private:
    std::vector<TimelineEvent> events;
};

// The CSV text (Csv.h), one row per event after a header row:
//     step,time,a,b,kind,normal_x,normal_y,depth,trigger
// time is step / stepsPerSecond in simulated seconds; kind is enter, stay or exit; numbers are
// written bit-exact (exactText); trigger is yes or no.
[[nodiscard]] std::string timelineCsv(const std::vector<TimelineEvent>& events);

} // namespace hitbox
