#include "hitbox/broadphase/ThreadCpuTime.h"

#include <ctime>

#if defined(_WIN32)
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>
#define HITBOX_THREAD_CPU_WINDOWS 1
#elif defined(__unix__) || defined(__APPLE__)
#include <time.h> // clock_gettime, CLOCK_THREAD_CPUTIME_ID (POSIX)
#if defined(CLOCK_THREAD_CPUTIME_ID)
#define HITBOX_THREAD_CPU_POSIX 1
#endif
#endif

namespace hitbox
{

double threadCpuSeconds()
{
#if defined(HITBOX_THREAD_CPU_WINDOWS)
    FILETIME created, exited, kernel, user;
    if (GetThreadTimes(GetCurrentThread(), &created, &exited, &kernel, &user))
    {
        // FILETIME counts 100-nanosecond units in two 32-bit halves.
        auto ticks = [](const FILETIME& time) {
            return (static_cast<unsigned long long>(time.dwHighDateTime) << 32) |
                   time.dwLowDateTime;
        };
        return static_cast<double>(ticks(kernel) + ticks(user)) * 1e-7;
    }
#elif defined(HITBOX_THREAD_CPU_POSIX)
    timespec now{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now) == 0)
        return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
#endif
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

bool threadCpuTimeIsPerThread()
{
#if defined(HITBOX_THREAD_CPU_WINDOWS) || defined(HITBOX_THREAD_CPU_POSIX)
    return true;
#else
    return false;
#endif
}

} // namespace hitbox
