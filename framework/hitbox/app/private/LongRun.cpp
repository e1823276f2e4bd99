#include "hitbox/app/private/LongRun.h"

#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>

namespace hitbox
{
namespace
{

// A signal handler may only set a flag of this type (C++17 [support.signal]); it is the one
// piece of state shared with the handler, so it cannot live in an object.
volatile std::sig_atomic_t interrupted = 0;

extern "C" void onInterrupt(int)
{
    interrupted = 1;
}

// "3 h 12 min", "4 min 5 s", "12 s": the rest of the run at the speed so far.
std::string duration(double seconds)
{
    const long long whole = static_cast<long long>(seconds + 0.5);
    if (whole >= 86400)
        return std::to_string(whole / 86400) + " d " + std::to_string(whole % 86400 / 3600) + " h";
    if (whole >= 3600)
        return std::to_string(whole / 3600) + " h " + std::to_string(whole % 3600 / 60) + " min";
    if (whole >= 60)
        return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
    return std::to_string(whole) + " s";
}

// The headless host (App.cpp's, plus the clock and the flag): one step per frame.
class ReportingHost : public LoopHost
{
public:
    ReportingHost(long long frames, const std::string& title) : total(frames), title(title) {}

    bool isRunning() const override { return done < total && interrupted == 0; }
    float secondsSinceLastFrame() override { return stepSeconds; }
    void processInput(Input&) override
    {
        ++done;
        // The clock is read every 1024 steps only: a step of a small level takes microseconds.
        if (done % 1024 == 0)
        {
            const double elapsed = secondsSince(start);
            if (elapsed >= nextReport)
            {
                std::cerr << progressLine(title, done, total, elapsed) << std::endl;
                nextReport = elapsed + progressSeconds;
            }
        }
    }
    int stepsToRun(int) override { return 1; }
    void render(const Level&, float) override {}

    long long stepsDone() const { return done; }

private:
    using Clock = std::chrono::steady_clock;
    static double secondsSince(Clock::time_point then)
    {
        return std::chrono::duration<double>(Clock::now() - then).count();
    }

    long long done = 0;
    long long total;
    std::string title;
    Clock::time_point start = Clock::now();
    double nextReport = progressSeconds;
};

} // namespace

std::string progressLine(const std::string& title, long long done, long long total,
                         double elapsedSeconds)
{
    const double fraction =
        total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
    char percent[32] = {};
    std::snprintf(percent, sizeof(percent), "%.1f", 100.0 * fraction);
    std::string line = title + ": " + std::to_string(done) + " of " + std::to_string(total) +
                       " steps simulated (" + percent + " %)";
    if (done > 0 && done < total)
        line += ", about " +
                duration(elapsedSeconds * static_cast<double>(total - done) /
                         static_cast<double>(done)) +
                " left";
    return line + "; Ctrl-C stops";
}

bool simulateReporting(Level& level, long long frames, const std::string& title)
{
    interrupted = 0;
    using Handler = void (*)(int);
    const Handler previous = std::signal(SIGINT, onInterrupt);
    ReportingHost host(frames, title);
    runLoop(level, host);
    std::signal(SIGINT, previous == SIG_ERR ? SIG_DFL : previous);
    if (interrupted == 0)
        return true;
    std::cerr << title << ": stopped by Ctrl-C after " << host.stepsDone() << " of " << frames
              << " steps; nothing more is printed or saved" << std::endl;
    return false;
}

} // namespace hitbox
