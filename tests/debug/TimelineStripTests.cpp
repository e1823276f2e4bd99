// The rewind strip's maths (TimelineStrip.h): steps to x and back, clamped, with the edges.
#include "hitbox/debug/TimelineStrip.h"

#include <gtest/gtest.h>

TEST(TimelineStrip, OldestAtTheLeftNewestAtTheRightAndClicksFindTheStep)
{
    const hitbox::Box area{100.f, 600.f, 1000.f, 20.f};
    const hitbox::StripRange range{200, 1200, 700};
    EXPECT_FLOAT_EQ(hitbox::stripXOf(area, range, 200), 100.f);
    EXPECT_FLOAT_EQ(hitbox::stripXOf(area, range, 1200), 1100.f);
    EXPECT_FLOAT_EQ(hitbox::stripXOf(area, range, 700), 600.f);
    EXPECT_FLOAT_EQ(hitbox::stripXOf(area, range, 5), 100.f) << "before the range: left edge";
    for (long long step : {200LL, 201LL, 699LL, 1200LL})
        EXPECT_EQ(hitbox::stripStepAt(area, range, hitbox::stripXOf(area, range, step)), step);
    EXPECT_EQ(hitbox::stripStepAt(area, range, -50.f), 200);
    EXPECT_EQ(hitbox::stripStepAt(area, range, 5000.f), 1200);
}

TEST(TimelineStrip, ARangeOfOneStepIsTheMiddleAndAnyClickGivesIt)
{
    const hitbox::Box area{0.f, 0.f, 400.f, 20.f};
    const hitbox::StripRange range{50, 50, 50};
    EXPECT_FLOAT_EQ(hitbox::stripXOf(area, range, 50), 200.f);
    EXPECT_EQ(hitbox::stripStepAt(area, range, 3.f), 50);
}
