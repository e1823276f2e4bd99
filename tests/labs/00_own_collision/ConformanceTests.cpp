// Grading tests of lab 0 (your own Collision class): the conformance pack at one place and
// size. Each suite is named after the task it checks; README.md lists them. A failure names
// the rule that was broken and prints both objects.
#include "ConformancePack.h"

#include <gtest/gtest.h>

namespace
{
const conformance::Variant visible{{0.f, 0.f}, 1.f, 1};
}

TEST(Task1WorldBox, FollowsOriginScaleRotationAndCollisionBox)
{
    conformance::checkWorldBox(visible);
}

TEST(Task2BoxAgainstBox, TouchingNeverCollides)
{
    conformance::checkBoxAgainstBox(visible);
}

TEST(Task3PointInBox, APointOnAnEdgeIsOutside)
{
    conformance::checkPointInBox(visible);
}

TEST(Task4BoundingCircle, CircleFromTheCollisionBoxAndTouchingNeverCollides)
{
    conformance::checkBoundingCircle(visible);
}

TEST(Task5CircleAgainstBox, TheClosestPointDecides)
{
    conformance::checkCircleAgainstBox(visible);
}
