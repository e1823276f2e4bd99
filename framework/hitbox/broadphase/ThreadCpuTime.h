// ThreadCpuTime.h - how much CPU time the calling thread has used: the clock that says what a
// piece of work costs whatever else the machine is running (wall-clock time also counts the
// time other programs had the core). The one platform-specific file of the broadphase layer.
#pragma once

namespace hitbox
{

// Seconds of CPU time the calling thread has used so far; only differences mean anything.
// Linux/macOS: clock_gettime(CLOCK_THREAD_CPUTIME_ID), nanoseconds. Windows: GetThreadTimes,
// which counts whole scheduler ticks (about 15.6 ms), so there a single step's figure is coarse
// and only averages over many steps are meaningful. Elsewhere: std::clock(), the whole
// process's CPU time (every thread added up); threadCpuTimeIsPerThread() says which.
[[nodiscard]] double threadCpuSeconds();

// True when threadCpuSeconds() counts only the calling thread (false: the std::clock fallback).
[[nodiscard]] bool threadCpuTimeIsPerThread();

} // namespace hitbox
