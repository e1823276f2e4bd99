// LongRun.h - a headless run that says how far it is and stops cleanly at Ctrl-C.
//
// `--seconds 100000000` is allowed (Options.h) and can take days: a silent terminal looks
// like a hang. So a run without a window prints one progress line on stderr every
// progressSeconds of wall time, and Ctrl-C ends it with one line instead of killing it
// mid-print. Only App.cpp and private/ScreenshotRun.cpp call this; tests use hitbox::simulate.
#pragma once

#include "hitbox/app/Level.h"

#include <string>

namespace hitbox
{

// Wall-clock seconds between two progress lines.
constexpr double progressSeconds = 5.0;

// The exit code after Ctrl-C (128 + SIGINT, what a shell reports for a program it stopped).
constexpr int stoppedExitCode = 130;

// Runs `frames` steps of `level` with no window. Prints "TITLE: N of M steps simulated
// (P %), about T left; Ctrl-C stops" on stderr every progressSeconds, nothing for a run
// shorter than that. Returns false when Ctrl-C stopped it; it has then printed the one line
// "TITLE: stopped by Ctrl-C after N of M steps; nothing more is printed or saved".
[[nodiscard]] bool simulateReporting(Level& level, long long frames, const std::string& title);

// One progress line as simulateReporting prints it (without the newline).
[[nodiscard]] std::string progressLine(const std::string& title, long long done, long long total,
                                       double elapsedSeconds);

} // namespace hitbox
