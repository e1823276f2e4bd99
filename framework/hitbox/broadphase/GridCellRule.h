// GridCellRule.h - THE GRID'S CELL RULE, in one place: how big GridBroadphase makes its cells
// when not given a size (and what lab 8 starts from).
//
// Small cells list each box in more cells; big cells test more pairs in each. Which costs more
// depends on how crowded the boxes are, so the rule weighs both with a cost model (the numbers
// are in docs/performance.md, "The cell rule"). For a cell k average sides wide, a box costs
//   kEntryCostInPairTests x (the cells it is listed in, (1 + 1/k)^2)
//   + (the pair tests it takes part in, coverage x (1 + k)^4 / (2 k^2)),
// where coverage = boxes x average side^2 / the area they spread over. The cheapest k solves
//   coverage x (1 + k)^2 x (k - 1) = 2 x kEntryCostInPairTests.
#pragma once

namespace hitbox
{

// Listing a box in one more cell costs about as much as this many pair tests: fitted so that
// the benchmark's boxes (coverage 0.75) get 3 sides, the size measured fastest for them.
constexpr double kEntryCostInPairTests = 12.0;
// Crowded boxes (coverage 0.75 and more) get cells this many average sides wide...
constexpr double kGridCellPerAverageSide = 3.0;
// ...and sparse ones up to this many (coverage about 0.1 and less; lab 8's crowd, 0.15, gets
// 5.2). Never more: the coverage is an average over all the boxes' area, and boxes crowded
// into one part of it pay for a bigger cell in pair tests (at 6, by the model, at most about
// 1.3 times what 3 would cost them).
constexpr double kGridCellPerAverageSideSparse = 6.0;

// How many average sides wide a cell should be for boxes covering `coverage` of the area they
// spread over: 3 from 0.75 up (and for an infinite coverage: boxes with no area to spread
// over), growing as the boxes thin out, 6 from about 0.1 down to 0. NaN or negative: 3.
[[nodiscard]] double gridCellPerAverageSide(double coverage);

// The cell size for boxes whose sides average `averageSide` and that cover `coverage` of the
// area they spread over: averageSide x gridCellPerAverageSide(coverage).
[[nodiscard]] double gridCellSizeFor(double averageSide, double coverage);

// The coverage of `count` boxes whose sides average `averageSide`, spread over a `width` x
// `height` area: count x averageSide^2 / (width x height). No area: infinite (0 for no boxes).
[[nodiscard]] double gridCoverage(double count, double averageSide, double width, double height);

} // namespace hitbox
