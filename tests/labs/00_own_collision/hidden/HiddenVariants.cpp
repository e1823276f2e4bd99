// The conformance pack's hidden variants: the same rules as ConformanceTests.cpp, moved to
// other places, at other sizes and with other random seeds. This folder never goes into
// the student handout (scripts/make-handout.sh leaves out every tests/labs/*/hidden/), so a
// class written to pass only the visible numbers fails here.
#include "ConformancePack.h"

#include <gtest/gtest.h>

namespace
{
const conformance::Variant hiddenVariants[] = {
    {{-1000.f, 512.f}, 0.5f, 20261123},
    {{3072.f, -4096.f}, 4.f, 977},
};
}

TEST(Task1WorldBoxHidden, OtherPlacesAndSizes)
{
    for (const conformance::Variant& variant : hiddenVariants)
        conformance::checkWorldBox(variant);
}

TEST(Task2BoxAgainstBoxHidden, OtherPlacesAndSizes)
{
    for (const conformance::Variant& variant : hiddenVariants)
        conformance::checkBoxAgainstBox(variant);
}

TEST(Task3PointInBoxHidden, OtherPlacesAndSizes)
{
    for (const conformance::Variant& variant : hiddenVariants)
        conformance::checkPointInBox(variant);
}

TEST(Task4BoundingCircleHidden, OtherPlacesAndSizes)
{
    for (const conformance::Variant& variant : hiddenVariants)
        conformance::checkBoundingCircle(variant);
}

TEST(Task5CircleAgainstBoxHidden, OtherPlacesAndSizes)
{
    for (const conformance::Variant& variant : hiddenVariants)
        conformance::checkCircleAgainstBox(variant);
}
