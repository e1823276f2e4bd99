#include "hitbox/app/ReplayLevel.h"

#include "hitbox/app/Input.h"

#include <utility>

namespace hitbox
{

void WrappedLevel::handleInput(const Input& input, float dt)
{
    inner.handleInput(input, dt);
}

void WrappedLevel::update(float dt)
{
    inner.update(dt);
    ++step;
}

void WrappedLevel::render(sf::RenderTarget& target) const
{
    inner.render(target);
}

void WrappedLevel::renderBlended(sf::RenderTarget& target, float leftover) const
{
    inner.renderBlended(target, leftover);
}

void WrappedLevel::renderDebug(DebugRenderer& debug) const
{
    inner.renderDebug(debug);
}

sf::Vector2f WrappedLevel::getWorldSize() const
{
    return inner.getWorldSize();
}

std::string WrappedLevel::getHelpText() const
{
    return inner.getHelpText();
}

std::string WrappedLevel::describeState() const
{
    return inner.describeState();
}

bool WrappedLevel::handleEscape()
{
    return inner.handleEscape();
}

std::vector<PairEvent> WrappedLevel::getContactEvents() const
{
    return inner.getContactEvents();
}

std::unique_ptr<LevelState> WrappedLevel::saveState() const
{
    return inner.saveState();
}

void WrappedLevel::restoreState(const LevelState& state)
{
    inner.restoreState(state);
}

void TimelineLevel::update(float dt)
{
    WrappedLevel::update(dt);
    timeline.addStep(step, inner.getContactEvents());
}

RecordingLevel::RecordingLevel(Level& inner, Recording header)
    : WrappedLevel(inner), recording(std::move(header))
{
    recording.steps = 0;
    recording.changes.clear();
}

void RecordingLevel::handleInput(const Input& input, float dt)
{
    recording.addStep(captureInput(input));
    inner.handleInput(input, dt);
}

ReplayingLevel::ReplayingLevel(Level& inner, Recording recording)
    : WrappedLevel(inner), recording(std::move(recording))
{
}

void ReplayingLevel::handleInput(const Input& input, float dt)
{
    if (step < recording.steps)
        inner.handleInput(restoreInput(recording.inputAt(step)), dt);
    else
        inner.handleInput(input, dt);
}

std::string ReplayingLevel::getHelpText() const
{
    const std::string where =
        step < recording.steps
            ? "replay step " + std::to_string(step) + " of " + std::to_string(recording.steps)
            : "replay ended at step " + std::to_string(recording.steps) + ": live input from here";
    return where + "   |   " + inner.getHelpText();
}

} // namespace hitbox
