#include "hitbox/app/ReplayLevel.h"

#include "hitbox/app/Input.h"

#include <utility>

namespace hitbox
{

void WrappedLevel::update(float dt)
{
    inner.update(dt);
    ++step;
}

void WrappedLevel::render(sf::RenderTarget& target) const
{
    inner.render(target);
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
    const std::string where = step < recording.steps
                                  ? "replay step " + std::to_string(step) + " of " +
                                        std::to_string(recording.steps)
                                  : "replay over: live input";
    return where + "   |   " + inner.getHelpText();
}

} // namespace hitbox
