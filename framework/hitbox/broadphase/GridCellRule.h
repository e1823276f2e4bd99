// GridCellRule.h - THE GRID'S CELL RULE, in one place: how big GridBroadphase makes its cells
// when not given a size (GridSettings::cellScale multiplies it: lab 8's [ and ]).
//
// Small cells list each box in more cells; big cells test more pairs in each. Which costs more
// depends on how crowded the boxes are, so the rule weighs both with a cost model (measured in
// docs/performance.md, "The cell rule"). For a cell k average sides wide:
//   - a box reaches across 1 + 1/k cells each way, so it is listed in (1 + 1/k)^2 cells;
//   - a cell then holds n = coverage x (1 + k)^2 listings, which make n^2 / 2 pair tests, so
//     each box's share of the tests (a test counted once, not once per box) is
//     coverage x (1 + k)^4 / (2 k^2);
// where coverage = boxes x average side^2 / the area they spread over (the rectangle around
// them, which in lab 8 is about the arena). Counting a listing as kEntryCostInPairTests
// tests, a box costs the sum of the two; the cheapest k solves
//   coverage x (1 + k)^2 x (k - 1) = 2 x kEntryCostInPairTests.
#pragma once

namespace hitbox
{

// Each cell a box is listed in costs about as much as this many pair tests. Fitted to one
// point: the benchmark's boxes (coverage 0.75) get 3 sides, the middle of the sizes measured
// fastest for them (2.5 to 4). The model's other answers are checked against lab 8's crowd.
constexpr double kEntryCostInPairTests = 12.0;
// Crowded boxes (coverage 0.75 and more) get cells this many average sides wide...
constexpr double kGridCellPerAverageSideCrowded = 3.0;
// ...and sparse ones up to this many (coverage 0.098 and less). Lab 8's crowd (coverage 0.15)
// gets 5.15; at 100,000 balls, whose smallest ones are held at 1 pixel across, 4.9. Never
// more, because the coverage is an average: boxes crowded into one part of their rectangle
// (a few stragglers far away) pay for a bigger cell in pair tests. At 6 instead of 3 the
// model charges boxes as crowded as the benchmark's about 1.3 times as much, at coverage 1.0
// 1.4 times, and never more than about 2.3 times.
constexpr double kGridCellPerAverageSideSparse = 6.0;
static_assert(kGridCellPerAverageSideCrowded >= 1.0 &&
                  kGridCellPerAverageSideCrowded <= kGridCellPerAverageSideSparse,
              "the crowded cell is the smaller one, at least one side wide");
static_assert(kEntryCostInPairTests > 0.0, "a listing costs something");

// How many average sides wide a cell should be for boxes covering `coverage` of the area they
// spread over: 3 from 0.75 up (and for an infinite coverage: boxes with no area to spread
// over), growing as the boxes thin out, 6 from 0.098 down to 0. NaN or negative: 3.
[[nodiscard]] double gridCellPerAverageSide(double coverage);

// The cell size for boxes whose sides average `averageSide` and that cover `coverage` of the
// area they spread over: averageSide x gridCellPerAverageSide(coverage) (NaN for a NaN side;
// GridBroadphase then makes one big cell).
[[nodiscard]] double gridCellSizeFor(double averageSide, double coverage);

// The coverage of `count` boxes whose sides average `averageSide`, spread over a `width` x
// `height` area: count x averageSide^2 / (width x height). No boxes: 0. No area (a width or
// height of 0 or less): infinite. A NaN side: NaN.
[[nodiscard]] double gridCoverage(double count, double averageSide, double width, double height);

} // namespace hitbox
