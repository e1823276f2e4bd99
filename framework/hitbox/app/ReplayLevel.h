// ReplayLevel.h - a Level wrapped so that its run is written down (RecordingLevel) or fed
// from what was written down (ReplayingLevel): --record and --replay (Replay.h) on any level,
// in the window, --headless or in a test, with no change to the loop or the level.
#pragma once

#include "hitbox/app/Level.h"
#include "hitbox/app/Replay.h"
#include "hitbox/app/Timeline.h"

namespace hitbox
{

// Everything but the input passed straight to the wrapped level.
class WrappedLevel : public Level
{
public:
    explicit WrappedLevel(Level& inner) : inner(inner) {}

    void handleInput(const Input& input, float dt) override;
    void update(float dt) override;
    void render(sf::RenderTarget& target) const override;
    void renderBlended(sf::RenderTarget& target, float leftover) const override;
    void renderDebug(DebugRenderer& debug) const override;
    [[nodiscard]] sf::Vector2f getWorldSize() const override;
    [[nodiscard]] std::string getHelpText() const override;
    [[nodiscard]] std::string describeState() const override;
    [[nodiscard]] bool handleEscape() override;
    [[nodiscard]] std::vector<PairEvent> getContactEvents() const override;
    [[nodiscard]] std::unique_ptr<LevelState> saveState() const override;
    void restoreState(const LevelState& state) override;

    // Fixed steps run so far.
    [[nodiscard]] long long getStep() const { return step; }

protected:
    Level& inner;
    long long step = 0;
};

// Writes down the input of every step, then passes it on.
class RecordingLevel : public WrappedLevel
{
public:
    RecordingLevel(Level& inner, Recording header);

    void handleInput(const Input& input, float dt) override;

    // The header given, with every step so far.
    [[nodiscard]] const Recording& getRecording() const { return recording; }

private:
    Recording recording;
};

// Writes down every contact event the level reports, step by step (--timeline).
class TimelineLevel : public WrappedLevel
{
public:
    explicit TimelineLevel(Level& inner) : WrappedLevel(inner) {}

    void update(float dt) override;

    [[nodiscard]] const Timeline& getTimeline() const { return timeline; }

private:
    Timeline timeline;
};

// Gives the level the recorded input of each step instead of the live one; after the last
// recorded step, the live input again (play on from where the recording ends).
class ReplayingLevel : public WrappedLevel
{
public:
    ReplayingLevel(Level& inner, Recording recording);

    void handleInput(const Input& input, float dt) override;
    [[nodiscard]] std::string getHelpText() const override;

private:
    Recording recording;
};

} // namespace hitbox
