// Level.h - the base class of every Hitbox program: a simulation you can also draw.
//
// hitbox::App runs a Level: it calls handleInput and update at a fixed step (stepsPerSecond
// times a second, Loop.h, whatever the frame rate), and renderBlended once per frame. Keep the
// rules in update and make render only read state: then tests can run the level with no window at
// all.
//
// (The course's framework calls its level base "BaseLevel"; that class still exists for
// course lab code, in framework/compat/Framework/BaseLevel.h. This one lives in namespace
// hitbox so a course lab's own `class Level` never clashes with it.)
#pragma once

#include "hitbox/objects/ContactEvent.h"

#include <SFML/System/Vector2.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace sf
{
class RenderTarget;
}

namespace hitbox
{
class Input;
class DebugRenderer;

// The game area of every program whose level does not override getWorldSize(), in world
// pixels (16:9, the shape of a lecture-hall projector).
inline const sf::Vector2f defaultWorldSize{1200.f, 675.f};

// A copy of everything a level's steps change, for rewinding (Rewind.h). Each level that can
// be rewound derives its own.
struct LevelState
{
    virtual ~LevelState() = default;
    // The memory it holds, in bytes (what the rewind reports it costs).
    [[nodiscard]] virtual std::size_t bytes() const = 0;
};

// "Copy the whole level": the snapshot of a level whose state is all plain values (vectors,
// numbers, no pointers into itself), so a copy of it is the state. saveState returns
// std::make_unique<WholeLevelCopy<MyLevel>>(*this, bytes); restoreState copies `level` back.
template <typename LevelType>
struct WholeLevelCopy : LevelState
{
    WholeLevelCopy(const LevelType& level, std::size_t held) : level(level), held(held) {}
    [[nodiscard]] std::size_t bytes() const override { return held; }

    LevelType level;
    std::size_t held; // what the copy holds, counted by the level (its vectors' elements too)
};

class Level
{
public:
    virtual ~Level() = default;

    // One fixed step: read the keyboard and the mouse (mouse in world coordinates).
    virtual void handleInput(const Input& input, float dt);
    // One fixed step: move things, test collisions, respond. dt is in seconds.
    virtual void update(float dt) = 0;
    // Draw the scene into `target`, in world coordinates. Reads state, changes nothing.
    virtual void render(sf::RenderTarget& target) const = 0;
    // Draw the scene `leftover` (0 to 1) of a step after the last step: the loop calls this
    // once per frame. A level whose things move fast draws them between where they were one
    // step ago (0) and where they are (1), so motion is smooth on a 60, 75 or 144 Hz screen
    // (Nystrom, "Game Loop", "Stuck in the middle"; Pong does). The default: render(target).
    virtual void renderBlended(sf::RenderTarget& target, float leftover) const;
    // Draw collision shapes, velocities and contacts (F1 shows them).
    virtual void renderDebug(DebugRenderer& debug) const;

    // The game area in world pixels (defaultWorldSize unless overridden); the window shows
    // exactly this area, letterboxed.
    [[nodiscard]] virtual sf::Vector2f getWorldSize() const;
    // This program's keys for the on-screen help line, e.g. "W/S move  Space serve".
    [[nodiscard]] virtual std::string getHelpText() const;
    // One line describing the state, printed at the end of a --headless run.
    [[nodiscard]] virtual std::string describeState() const;
    // The contact events (enter, stay, exit) of the last step, for --timeline and the rewind
    // strip (Timeline.h). A level with a World returns world.getEvents(); by default none.
    [[nodiscard]] virtual std::vector<PairEvent> getContactEvents() const;
    // Rewinding (Rewind.h): a copy of the state, or nullptr (the default): then the window
    // rewinds by building the level again and re-simulating from step 0 (RewindReplay.h),
    // which costs more the longer the run. restoreState gets back exactly a state saveState
    // gave: afterwards the same input must give the same steps, bit for bit.
    [[nodiscard]] virtual std::unique_ptr<LevelState> saveState() const;
    virtual void restoreState(const LevelState& state);
    // Escape was pressed. Return true if the level used it (e.g. back to a menu);
    // false lets the program quit.
    [[nodiscard]] virtual bool handleEscape();
};

} // namespace hitbox
