// Platform.h - the one place Hitbox asks the operating system something that C++17 does not
// say how to ask portably. Everything else in Hitbox (and its tests) calls these instead of
// getenv, localtime, getpid, setenv, readlink or dlopen, for two reasons:
//  - Microsoft's C runtime deprecates getenv, localtime, strerror, getpid (warning C4996,
//    "This function or variable may be unsafe"), an error under /WX. Its replacements
//    (_dupenv_s, localtime_s, _getpid) do not exist on Linux or macOS.
//  - POSIX calls (setenv, readlink, dlopen, mkfifo, setrlimit) do not exist on Windows.
// Platform.cpp holds both spellings of each, chosen by the preprocessor. Knows no SFML.
#pragma once

#include <cstdint>
#include <ctime>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace hitbox::platform
{

// The variable's value; nullopt when it is not set (or the name is empty or has a '=').
// A variable set to "" is "", not nullopt.
[[nodiscard]] std::optional<std::string> environmentVariable(const std::string& name);

// Sets (or with unsetEnvironmentVariable removes) a variable of this process and the programs
// it starts; for tests and tools. False for an empty name, a name with '=', or a refusal.
// On Windows the C runtime's own copy (getenv) is not updated: read with environmentVariable.
[[nodiscard]] bool setEnvironmentVariable(const std::string& name, const std::string& value);
[[nodiscard]] bool unsetEnvironmentVariable(const std::string& name);

// `when` in the computer's time zone, as std::localtime gives it, without its shared buffer.
[[nodiscard]] std::tm localTime(std::time_t when);

// This process's id: tells apart two runs' temporary files.
[[nodiscard]] long processId();

// The folder holding the running program; "." when the system does not say (macOS here).
[[nodiscard]] std::string programFolder();

// A shared library loaded at run time, unloaded when the last copy is destroyed; null when it
// cannot be loaded, and always null on Windows and macOS (only Linux's X11 check needs one).
[[nodiscard]] std::shared_ptr<void> loadLibrary(const std::string& name);
// The address of `symbol` in `library`; null when it is not there or the library is null.
[[nodiscard]] void* findSymbol(const std::shared_ptr<void>& library, const std::string& symbol);

// For tests of what a program does on a device and on a full disk.
// Makes a named pipe at `path`: false where there are none (Windows) or when it fails.
[[nodiscard]] bool makeNamedPipe(const std::string& path);
// Runs `work` with every file this process writes limited to `bytes` (writes past it fail
// instead of stopping the process): false, and `work` not run, where there is no such limit.
[[nodiscard]] bool runWithFileSizeLimit(std::uintmax_t bytes, const std::function<void()>& work);

// What a grader wrote to the pipe whose descriptor number the environment variable `variable`
// holds, read to its end (at most about 4 KB); the descriptor is closed afterwards, so later
// code cannot read it. "" when the variable is unset, not a number above 2, or on Windows
// (class grading runs on Linux only).
[[nodiscard]] std::string takeInheritedPipe(const std::string& variable);

// Seconds of CPU time the calling thread has used so far; only differences mean anything: the
// clock that says what a piece of work costs whatever else the machine runs (wall-clock time
// also counts the time other programs had the core). Linux/macOS:
// clock_gettime(CLOCK_THREAD_CPUTIME_ID), nanoseconds. Windows: GetThreadTimes, which counts
// whole scheduler ticks (about 15.6 ms), so there only averages over many steps mean much.
// Elsewhere: std::clock(), the whole process's CPU time; threadCpuTimeIsPerThread() says which.
[[nodiscard]] double threadCpuSeconds();

// True when threadCpuSeconds() counts only the calling thread (false: the std::clock fallback).
[[nodiscard]] bool threadCpuTimeIsPerThread();

} // namespace hitbox::platform
