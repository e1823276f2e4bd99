// Grading tests of lab 11 (Pong).
#include "PongLevel.h"

#include <gtest/gtest.h>

TEST(Level, Builds)
{
    PongLevel level;
    EXPECT_EQ(level.getLeftScore(), 0);
}
