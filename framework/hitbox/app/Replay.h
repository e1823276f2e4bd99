// Replay.h - a run written down: the seed, the level's options and the input every fixed step
// saw, enough to run it again exactly (--record FILE, --replay FILE; docs/debugging.md).
//
// The simulation is fixed-step and deterministic (Loop.h): the same level, built from the same
// options and seed, fed the same input at the same steps, ends in the same state bit for bit.
// So a replay stores no positions, only what came from outside: the input of each step.
//
// The file is CSV (Csv.h), one record per row, the kind of record in the first field:
//     hitbox-replay,1                     always the first row: the format and its version
//     program,Pong                        the title of the program that recorded it
//     seed,1                              --seed
//     headless,no                         whether the recording ran without a window
//     option,--mode,2p                    each of the program's own options that was given
//     steps,1200                          how many fixed steps were recorded
//     input,STEP,DOWN,PRESSED,RELEASED,MOUSE_X,MOUSE_Y,LEFT,RIGHT,WHEEL
// An input row gives the input from step STEP (counted from 0) until the next input row:
// DOWN, PRESSED and RELEASED are key codes (sf::Keyboard::Key) separated by spaces, the mouse
// is in world coordinates (exactText, bit-exact), LEFT and RIGHT are the buttons' flags (d down,
// p pressed this step, r released this step; empty: up), WHEEL the wheel's movement this step.
#pragma once

#include "hitbox/app/Input.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hitbox
{

// The version written in the first row. A file of another version is refused, never guessed.
constexpr int replayFormatVersion = 1;

struct ButtonSnapshot
{
    bool down = false;
    bool pressed = false;
    bool released = false;
};

// What one step saw through Input's getters: all a level can read, so all a replay must give.
struct InputSnapshot
{
    std::vector<int> keysDown; // key codes, ascending
    std::vector<int> keysPressed;
    std::vector<int> keysReleased;
    float mouseX = 0.f;
    float mouseY = 0.f;
    ButtonSnapshot left;
    ButtonSnapshot right;
    float wheel = 0.f;
};

// True when the two are the same bit for bit (a NaN equals the same NaN).
[[nodiscard]] bool sameInput(const InputSnapshot& a, const InputSnapshot& b);

// The snapshot of `input` now.
[[nodiscard]] InputSnapshot captureInput(const Input& input);
// An Input whose every getter answers what `snapshot` says.
[[nodiscard]] Input restoreInput(const InputSnapshot& snapshot);

struct Recording
{
    std::string program;
    unsigned seed = 1;
    bool headless = false;
    std::map<std::string, std::string> options; // the program's own options, as typed
    long long steps = 0;
    // (step, input from that step on), steps ascending; the input before the first is empty.
    std::vector<std::pair<long long, InputSnapshot>> changes;

    // Adds the input of step `steps` (a row only when it differs from the step before).
    void addStep(const InputSnapshot& input);
    // The input step `step` saw.
    [[nodiscard]] InputSnapshot inputAt(long long step) const;
};

// The file's text (the format above).
[[nodiscard]] std::string replayText(const Recording& recording);

struct ReplayRead
{
    bool read = false;
    Recording recording;
    std::string problem; // when not read: why, in one line, e.g. "row 3: seed needs a number"

    explicit operator bool() const { return read; }
};

// Reads a replay from its text, or from the file at `path`.
[[nodiscard]] ReplayRead readReplayText(const std::string& text);
[[nodiscard]] ReplayRead readReplayFile(const std::string& path);

} // namespace hitbox
