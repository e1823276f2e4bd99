// LongAgreementTest.cpp - the agreement checks on 10^6 random cases each (label `long`).
// The checks, references and tolerances are in support/GeometryAgreement.h.
#include "support/GeometryAgreement.h"

#include <gtest/gtest.h>

namespace
{
constexpr long cases = 1000000;
}

TEST(LongAgreement, SweptCirclesMatchABruteForceWalkAlongTheMotion)
{
    agreement::expectAgreement(agreement::sweptCircles(cases, 101u), cases);
}

TEST(LongAgreement, SweptCircleVsBoxMatchesABruteForceWalkAlongTheMotion)
{
    agreement::expectAgreement(agreement::sweptCircleVsBox(cases, 102u), cases);
}

TEST(LongAgreement, SweptBoxesAndSegmentsMatchABruteForceWalkAlongTheMotion)
{
    agreement::expectAgreement(agreement::sweptBoxes(cases, 103u), cases);
}

TEST(LongAgreement, SatMatchesEdgeCrossingsAndTheMinkowskiDifference)
{
    agreement::expectAgreement(agreement::polygonsWithFractions(cases, 104u), cases);
}

TEST(LongAgreement, SatIsExactOnWholeNumberPolygonsIncludingTouchingAndFlatOnes)
{
    agreement::expectAgreement(agreement::polygonsWithWholeNumbers(cases, 105u), cases);
}

TEST(LongAgreement, CapsulesMatchPointToSegmentDistances)
{
    agreement::expectAgreement(agreement::capsules(cases, 106u), 3 * cases);
}
