// AgreementTest.cpp - 10^5 seeded random cases per family of shapes, each checked against an
// independent reference (support/GeometryReference.h; tolerance and why in
// support/GeometryAgreement.h). The `long` label runs the same checks on 10^6 cases.

// No `#pragma GCC optimize` here to speed the references up: optimisation is the build
// type's choice. The pragma gives this file optimised copies of inline functions that other
// files also have (std::mt19937's generator), and the GCC manual ("Common Function
// Attributes", optimize) says it is for debugging only, "not suitable in production code".

#include "support/GeometryAgreement.h"

#include "hitbox/geometry/Resolve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// Slide past a corner that only touches (issue 19): a box moving diagonally hits the near
// face of one solid and slides along it, past a second solid whose side it only touches.
// The answer is known exactly: it ends flush with the first solid, the whole move done on
// the other axis. Random sizes, places and speeds, mirrored and turned into all 8 directions.
TEST(Agreement, ASlidingBoxGoesOnPastACornerItOnlyTouches)
{
    std::mt19937 random(6u);
    std::uniform_int_distribution<int> place(-500, 500), size(1, 40), extra(1, 200);
    auto mirror = [](hitbox::Box box, bool flipX, bool flipY, bool swap)
    {
        if (swap)
            box = {box.top, box.left, box.height, box.width};
        if (flipX)
            box.left = -(box.left + box.width);
        if (flipY)
            box.top = -(box.top + box.height);
        return box;
    };
    long failures = 0;
    for (long i = 0; i < cases / 10; ++i)
    {
        // In the canonical frame: box (x, y, s, s) moving (m, m) with m > s; the first solid
        // starts one box width to the right and one down, the second right under the box.
        const float x = float(place(random)), y = float(place(random)), s = float(size(random));
        const float m = s + float(extra(random));
        const hitbox::Box first{x + 2.f * s, y + s, float(size(random)), float(size(random))};
        const hitbox::Box second{x, y + 2.f * s, s, float(size(random)) + m};
        const hitbox::Box expected{x + s, y + m, s, s};
        const bool flipX = random() % 2, flipY = random() % 2, swap = random() % 2;
        const hitbox::Vec2 turned(flipX ? -m : m, flipY ? -m : m); // (m, m) is its own swap
        const hitbox::MoveResult result = hitbox::moveBoxAndSlide(
            mirror({x, y, s, s}, flipX, flipY, swap), turned, 1.f,
            {mirror(first, flipX, flipY, swap), mirror(second, flipX, flipY, swap)});
        const hitbox::Box want = mirror(expected, flipX, flipY, swap);
        const float tolerance = 1e-3f * m;
        if (std::fabs(result.box.left - want.left) > tolerance ||
            std::fabs(result.box.top - want.top) > tolerance || result.hits.size() != 1u)
        {
            if (++failures <= 3)
                ADD_FAILURE() << "case " << i << ": box (" << x << ", " << y << ", " << s
                              << ") move " << m << " flips " << flipX << flipY << swap
                              << " ended at (" << result.box.left << ", " << result.box.top
                              << ") with " << result.hits.size() << " hits, want (" << want.left
                              << ", " << want.top << ")";
        }
    }
    EXPECT_EQ(failures, 0);
}
