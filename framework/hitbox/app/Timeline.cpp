#include "hitbox/app/Timeline.h"

#include "hitbox/app/Csv.h"
#include "hitbox/app/Loop.h"
#include "hitbox/objects/GameObject.h"

#include <algorithm>
#include <sstream>

namespace hitbox
{
namespace
{

std::string nameOf(const GameObject* object)
{
    if (object == nullptr)
        return "(destroyed)";
    return object->getName().empty() ? object->describe() : object->getName();
}

} // namespace

void Timeline::addStep(long long step, const std::vector<PairEvent>& stepEvents)
{
    for (const PairEvent& event : stepEvents)
        events.push_back({step, nameOf(event.first), nameOf(event.second), event.phase,
                          event.contact.normal, event.contact.depth, event.trigger});
}

void Timeline::dropAfter(long long step)
{
    events.erase(std::find_if(events.begin(), events.end(),
                              [step](const TimelineEvent& event) { return event.step > step; }),
                 events.end());
}

std::string timelineCsv(const std::vector<TimelineEvent>& events)
{
    std::ostringstream text;
    CsvWriter csv(text);
    csv.row({"step", "time", "a", "b", "kind", "normal_x", "normal_y", "depth", "trigger"});
    for (const TimelineEvent& event : events)
        csv.row({std::to_string(event.step),
                 exactText(static_cast<float>(static_cast<double>(event.step) /
                                              static_cast<double>(stepsPerSecond))),
                 event.a, event.b, toString(event.kind), exactText(event.normal.x),
                 exactText(event.normal.y), exactText(event.depth), event.trigger ? "yes" : "no"});
    return text.str();
}

} // namespace hitbox
