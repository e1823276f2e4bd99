#include "StepTiming.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

TimingSummary StepTiming::summarise(double budgetMilliseconds) const
{
    TimingSummary summary;
    summary.steps = samples.size();
    if (samples.empty())
        return summary;
    std::vector<double> totals;
    totals.reserve(samples.size());
    double total = 0.0, broadphase = 0.0, exact = 0.0;
    for (const StepSample& sample : samples)
    {
        totals.push_back(sample.total * 1000.0);
        total += sample.total;
        broadphase += sample.broadphase;
        exact += sample.exactTests;
        summary.overBudget += sample.total * 1000.0 > budgetMilliseconds ? 1 : 0;
    }
    std::sort(totals.begin(), totals.end());
    // Nearest rank: the smallest value with at least p of the samples at or below it.
    auto percentile = [&totals](double p)
    {
        const double rank = std::ceil(p * static_cast<double>(totals.size()));
        const std::size_t index = static_cast<std::size_t>(std::max(rank, 1.0)) - 1;
        return totals[std::min(index, totals.size() - 1)];
    };
    summary.medianMilliseconds = percentile(0.5);
    summary.p99Milliseconds = percentile(0.99);
    summary.maxMilliseconds = totals.back();
    if (total > 0.0)
    {
        summary.broadphaseShare = std::min(1.0, broadphase / total);
        summary.exactTestShare = std::min(1.0 - summary.broadphaseShare, exact / total);
        summary.responseShare = 1.0 - summary.broadphaseShare - summary.exactTestShare;
    }
    return summary;
}

std::string describeTiming(const TimingSummary& summary, double budgetMilliseconds)
{
    char text[256];
    std::snprintf(text, sizeof(text),
                  "CPU per step: median %.2f ms, p99 %.2f, max %.2f over %zu steps (%zu over "
                  "%.2f ms); broadphase %.0f %%, exact tests %.0f %%, response %.0f %%",
                  summary.medianMilliseconds, summary.p99Milliseconds, summary.maxMilliseconds,
                  summary.steps, summary.overBudget, budgetMilliseconds,
                  summary.broadphaseShare * 100.0, summary.exactTestShare * 100.0,
                  summary.responseShare * 100.0);
    return text;
}
