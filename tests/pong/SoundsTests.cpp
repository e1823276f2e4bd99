// The synthesized beeps (no audio device needed: only the samples are made here).
#include "Sounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

TEST(Sounds, ABeepHasTheRequestedLength)
{
    EXPECT_EQ(synthesizeBeep(460.f, 0.05f, 44100).size(), 2205u);
    EXPECT_TRUE(synthesizeBeep(460.f, 0.f, 44100).empty());
}

TEST(Sounds, ABeepIsAudibleButNotFullScaleAndEndsSilentlyWithoutAClick)
{
    const std::vector<std::int16_t> beep = synthesizeBeep(460.f, 0.05f, 44100);
    int loudest = 0;
    for (std::int16_t sample : beep)
        loudest = std::max(loudest, std::abs(static_cast<int>(sample)));
    EXPECT_GT(loudest, 4000);
    EXPECT_LT(loudest, 16000);
    EXPECT_LT(std::abs(static_cast<int>(beep.back())), 500);
}
