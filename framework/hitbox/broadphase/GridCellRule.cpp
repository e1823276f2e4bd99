#include "hitbox/broadphase/GridCellRule.h"

#include <limits>

namespace hitbox
{

double gridCellPerAverageSide(double coverage)
{
    if (!(coverage >= 0.0))
        return kGridCellPerAverageSideCrowded; // NaN or negative: the crowded rule, the safe one
    // The cost model's balance (GridCellRule.h): it grows with k, so the cheapest k lies where
    // it reaches the target, found by halving [3, 6].
    const auto balance = [coverage](double k)
    { return coverage * (1.0 + k) * (1.0 + k) * (k - 1.0); };
    const double target = 2.0 * kEntryCostInPairTests;
    double low = kGridCellPerAverageSideCrowded;
    double high = kGridCellPerAverageSideSparse;
    if (balance(low) >= target)
        return low;
    if (balance(high) <= target)
        return high;
    for (int halving = 0; halving < 60; ++halving)
    {
        const double middle = 0.5 * (low + high);
        if (balance(middle) < target)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}

double gridCellSizeFor(double averageSide, double coverage)
{
    return averageSide * gridCellPerAverageSide(coverage);
}

double gridCoverage(double count, double averageSide, double width, double height)
{
    if (!(count > 0.0))
        return 0.0;
    if (!(width > 0.0 && height > 0.0))
        return std::numeric_limits<double>::infinity();
    return count * averageSide * averageSide / (width * height);
}

} // namespace hitbox
