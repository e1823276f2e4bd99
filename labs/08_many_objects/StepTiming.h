// StepTiming.h - what each collision step cost in CPU time, and the figures --print-timing
// shows: median, p99 and max over the steps since the last line, how many steps went over
// the budget of one step (8.33 ms at 120 steps a second), and where the time went.
// CPU time, not wall-clock time: it does not grow when other programs share the cores, so a
// student reads the same figures on a busy machine (hitbox::platform::threadCpuSeconds, the one
// platform-specific clock). Plain data: no SFML, no clock of its own.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

// One step's CPU seconds: the whole of findPairsAndRespond, and its broadphase part. With two
// threads, the longest chain: the calling thread's time plus what the second thread spent
// beyond it. `exactTests` is timed apart on the step's pairs (see ManyObjectsLevel.cpp).
struct StepSample
{
    double total = 0.0;
    double broadphase = 0.0;
    double exactTests = 0.0;
};

struct TimingSummary
{
    std::size_t steps = 0;
    double medianMilliseconds = 0.0, p99Milliseconds = 0.0, maxMilliseconds = 0.0;
    std::size_t overBudget = 0; // steps over budgetMilliseconds
    // Shares of the total, 0 to 1: broadphase, exact tests, and the rest (response and loop).
    double broadphaseShare = 0.0, exactTestShare = 0.0, responseShare = 0.0;
};

class StepTiming
{
public:
    void add(const StepSample& sample) { samples.push_back(sample); }
    [[nodiscard]] std::size_t size() const { return samples.size(); }
    void clear() { samples.clear(); }
    // The figures over the samples so far; all zero when there are none. Percentiles are the
    // nearest rank (p99 of 100 steps is the 99th smallest).
    [[nodiscard]] TimingSummary summarise(double budgetMilliseconds) const;

private:
    std::vector<StepSample> samples;
};

// "CPU per step: median 2.41 ms, p99 3.02, max 3.50 over 1,200 steps (0 over 8.33 ms);
// broadphase 61 %, exact tests 14 %, response 25 %".
[[nodiscard]] std::string describeTiming(const TimingSummary& summary, double budgetMilliseconds);
