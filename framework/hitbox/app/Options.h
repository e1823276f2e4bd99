// Options.h - the command line every Hitbox program shares, and typed getters for a
// program's own options, all with ONE message format:
//     Lab 8 - Many objects: --balls needs a whole number from 1 to 20000, not 'abc'
// A bad value throws std::invalid_argument; hitbox::run prints the line and exits with 2.
#pragma once

#include "hitbox/app/Loop.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace hitbox
{

struct ProgramInfo
{
    std::string title;                          // the window title, e.g. "Pong"
    std::vector<std::string> extraOptions = {}; // options this program reads, each with a value
};

// The largest --seconds (--frames: as many steps): about three years of simulated time, far
// beyond any run anyone waits for, and small enough that a frame count never overflows.
constexpr long long maxSeconds = 100'000'000;
// The largest --frames and --pause-at-step: maxSeconds of fixed steps.
constexpr long long maxSteps = maxSeconds * static_cast<long long>(stepsPerSecond);
// How many steps --headless runs when --frames and --seconds are not given.
constexpr long long headlessDefaultSteps = 600;

struct Options
{
    bool help = false; // --help or -h: print usagePage() and do nothing else
    bool headless = false;
    long long frames = -1; // -1: not given
    std::string screenshotPath;
    bool debugBoxes = false;
    unsigned seed = 1;
    std::string recordPath;     // --record FILE: write the run's input down (Replay.h)
    std::string replayPath;     // --replay FILE: run a recorded run again
    std::string timelinePath;   // --timeline FILE.csv: every contact event (Timeline.h)
    long long pauseAtStep = -1; // --pause-at-step N: the window pauses after N steps; -1 never
    std::map<std::string, std::string> extra; // the ProgramInfo::extraOptions that were given

    // A --screenshot run draws a picture that must be the same on every run (the slides'
    // figures and the lab sheets' pictures are drawn twice and compared): a level leaves out
    // what depends on the machine or the moment (CPU or wall-clock timings, clocks). F12 in a
    // window saves the window as it is, timings included.
    [[nodiscard]] bool repeatablePicture() const { return !screenshotPath.empty(); }

    // The value of an extra option as typed, or `fallback` when it was not given.
    [[nodiscard]] std::string get(const std::string& name, const std::string& fallback) const;

    // The typed getters: `fallback` when the option was not given; a value that is not of
    // the type or outside lowest..highest (inclusive) throws std::invalid_argument.
    // Digits only, an optional leading '-': "1e9", "12abc", " 5" and "+5" are refused.
    [[nodiscard]] long long wholeNumber(const std::string& name, long long fallback,
                                        long long lowest, long long highest) const;
    // A decimal number such as 0.5, -2 or 3.25: digits, an optional leading '-' and one
    // optional '.' with digits after it. "1e3", "0x10", ".5", "5.", " 5" and "+5" are refused.
    [[nodiscard]] double number(const std::string& name, double fallback, double lowest,
                                double highest) const;
    // Exactly "on" or "off".
    [[nodiscard]] bool onOff(const std::string& name, bool fallback) const;
    // One of `choices`, spelled exactly (`fallback` need not be one: e.g. "" for none).
    [[nodiscard]] std::string oneOf(const std::string& name, const std::string& fallback,
                                    const std::vector<std::string>& choices) const;
};

// Reads the command line. Throws std::invalid_argument with a one-line message. Each option
// may be given once, and --frames and --seconds not together: a second value would silently
// win over the first, so it is refused. --help or -h anywhere: help is set, nothing else read.
[[nodiscard]] Options parseOptions(int argc, const char* const argv[], const ProgramInfo& info);

// The page --help prints: what the program is, every shared option and this program's own.
[[nodiscard]] std::string usagePage(const ProgramInfo& info);

// `text` made safe for a one-line message: printable ASCII stays, every other byte is
// written as an escape (\r, \t, \0, \xEF), and anything past `longest` bytes becomes "...".
[[nodiscard]] std::string printable(const std::string& text, std::size_t longest = 60);

} // namespace hitbox
