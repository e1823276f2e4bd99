// AgreementTest.cpp - 10^5 seeded random cases per family of shapes, each checked against an
// independent reference (support/GeometryReference.h; tolerance and why in
// support/GeometryAgreement.h). The `long` label runs the same checks on 10^6 cases.

// The references are slow unoptimised (10^5 convex hulls of 64 points each), so this one file
// is optimised even in debug builds, to keep the default run quick. The geometry code under
// test is still built as the preset says. GCC only; clang builds it unoptimised.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("O2")
#endif

#include "support/GeometryAgreement.h"

#include <gtest/gtest.h>

namespace
{
constexpr long cases = 100000;
}

TEST(Agreement, SweptCirclesMatchABruteForceWalkAlongTheMotion)
{
    agreement::expectAgreement(agreement::sweptCircles(cases, 1u), cases);
}

TEST(Agreement, SweptCircleVsBoxMatchesABruteForceWalkAlongTheMotion)
{
    agreement::expectAgreement(agreement::sweptCircleVsBox(cases, 2u), cases);
}

TEST(Agreement, SweptBoxesAndSegmentsMatchABruteForceWalkAlongTheMotion)
{
    agreement::expectAgreement(agreement::sweptBoxes(cases, 3u), cases);
}

TEST(Agreement, SatMatchesEdgeCrossingsAndTheMinkowskiDifference)
{
    agreement::expectAgreement(agreement::polygonsWithFractions(cases, 4u), cases);
}

TEST(Agreement, SatIsExactOnWholeNumberPolygonsIncludingTouchingAndFlatOnes)
{
    agreement::expectAgreement(agreement::polygonsWithWholeNumbers(cases, 5u), cases);
}

TEST(Agreement, CapsulesMatchPointToSegmentDistances)
{
    // Three tests per case: capsule vs capsule, vs circle, vs polygon.
    agreement::expectAgreement(agreement::capsules(cases, 6u), 3 * cases);
}
