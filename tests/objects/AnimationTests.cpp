// Animation: frames on a sprite sheet, advanced by time, looping or stopping, mirrored.
#include "support/SfmlPrinters.h"

#include "hitbox/objects/Animation.h"
#include "hitbox/sfml/Graphics.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>

using hitbox::Animation;

namespace
{

std::string describe(const sf::IntRect& frame)
{
    std::ostringstream text;
    const sf::Vector2i position = hitbox::rectPosition(frame);
    const sf::Vector2i size = hitbox::rectSize(frame);
    text << "IntRect{x=" << position.x << ", y=" << position.y << ", w=" << size.x
         << ", h=" << size.y << "}";
    return text.str();
}

// Three 16 x 24 frames side by side, a quarter of a second each (exact in binary, so
// "exactly at the end of a frame" means what it says).
Animation threeFrameWalk()
{
    Animation walk;
    walk.addFrame(sf::IntRect({0, 0}, {16, 24}));
    walk.addFrame(sf::IntRect({16, 0}, {16, 24}));
    walk.addFrame(sf::IntRect({32, 0}, {16, 24}));
    walk.setFrameSpeed(0.25f);
    return walk;
}

} // namespace

TEST(Animation, StartsOnTheFirstFramePlayingAndLooping)
{
    const Animation walk = threeFrameWalk();
    EXPECT_EQ(walk.getSize(), 3);
    EXPECT_EQ(walk.getCurrentFrame(), sf::IntRect({0, 0}, {16, 24}))
        << describe(walk.getCurrentFrame());
    EXPECT_TRUE(walk.getPlaying());
    EXPECT_TRUE(walk.getLooping());
    EXPECT_FALSE(walk.getFlipped());
}

TEST(Animation, MovesOnWhenAFramesTimeIsUp)
{
    Animation walk = threeFrameWalk();
    walk.animate(0.2f);
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
    walk.animate(0.05f); // 0.25 s in total: the first frame's time is up
    EXPECT_EQ(walk.getCurrentFrameIndex(), 1);
    EXPECT_EQ(walk.getCurrentFrame(), sf::IntRect({16, 0}, {16, 24}))
        << describe(walk.getCurrentFrame());
}

TEST(Animation, SpeedDoesNotDependOnTheFrameRate)
{
    // 0.625 s (two and a half frames) at 64 and at 8 game frames a second: the same frame.
    Animation fast = threeFrameWalk();
    Animation slow = threeFrameWalk();
    for (int frame = 0; frame < 40; ++frame)
        fast.animate(1.f / 64.f);
    for (int frame = 0; frame < 5; ++frame)
        slow.animate(1.f / 8.f);
    EXPECT_EQ(fast.getCurrentFrameIndex(), 2);
    EXPECT_EQ(slow.getCurrentFrameIndex(), 2);
}

TEST(Animation, ALongStallSkipsFramesInsteadOfLosingTime)
{
    Animation walk = threeFrameWalk();
    walk.animate(0.5f); // two frames' worth in one call
    EXPECT_EQ(walk.getCurrentFrameIndex(), 2);
}

TEST(Animation, LoopingGoesBackToTheFirstFrame)
{
    Animation walk = threeFrameWalk();
    walk.animate(0.75f);
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
    EXPECT_TRUE(walk.getPlaying());
    walk.animate(10.f * 0.75f + 0.25f); // ten whole loops and one frame
    EXPECT_EQ(walk.getCurrentFrameIndex(), 1);
}

TEST(Animation, NotLoopingStopsOnTheLastFrame)
{
    Animation jump = threeFrameWalk();
    jump.setLooping(false);
    jump.animate(0.5f);
    EXPECT_EQ(jump.getCurrentFrameIndex(), 2);
    EXPECT_TRUE(jump.getPlaying());
    jump.animate(0.25f);
    EXPECT_EQ(jump.getCurrentFrameIndex(), 2);
    EXPECT_FALSE(jump.getPlaying());
    jump.animate(5.f);
    EXPECT_EQ(jump.getCurrentFrameIndex(), 2);
}

TEST(Animation, PausedHoldsTheFrameAndResetGoesBackToTheStart)
{
    Animation walk = threeFrameWalk();
    walk.animate(0.3f);
    walk.setPlaying(false);
    walk.animate(1.f);
    EXPECT_EQ(walk.getCurrentFrameIndex(), 1);
    walk.reset();
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
    walk.setPlaying(true);
    walk.animate(0.2f); // the 0.05 s left over before reset() is gone
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
}

// The 2025-26 course's stop() and pause(): both stop playing; only stop() rewinds.
TEST(Animation, PauseKeepsTheFrameAndItsTimeStopRewinds)
{
    Animation walk = threeFrameWalk();
    walk.animate(0.375f); // frame 1, 0.125 s into it
    walk.pause();
    EXPECT_FALSE(walk.isPlaying());
    walk.animate(1.f);
    EXPECT_EQ(walk.getCurrentFrameIndex(), 1);
    walk.setPlaying(true);
    walk.animate(0.125f); // the 0.125 s before pause() still count: frame 1's time is up
    EXPECT_EQ(walk.getCurrentFrameIndex(), 2);

    walk.stop();
    EXPECT_FALSE(walk.isPlaying());
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
    walk.setPlaying(true);
    walk.animate(0.2f); // no time carried over from before stop()
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
}

TEST(Animation, FlippedFrameIsMirroredWithANegativeWidth)
{
    Animation walk = threeFrameWalk();
    walk.animate(0.25f);
    walk.setFlipped(true);
    // Starts at the frame's right edge (16 + 16) and runs 16 pixels leftwards.
    EXPECT_EQ(walk.getCurrentFrame(), sf::IntRect({32, 0}, {-16, 24}))
        << describe(walk.getCurrentFrame());
    walk.setFlipped(false);
    EXPECT_EQ(walk.getCurrentFrame(), sf::IntRect({16, 0}, {16, 24}))
        << describe(walk.getCurrentFrame());
}

TEST(Animation, EmptyAnimationGivesAnEmptyFrameAndNeverCrashes)
{
    Animation nothing;
    nothing.animate(1.f);
    nothing.setFlipped(true);
    EXPECT_EQ(nothing.getSize(), 0);
    EXPECT_EQ(nothing.getCurrentFrame(), sf::IntRect()) << describe(nothing.getCurrentFrame());
}

TEST(Animation, ZeroNegativeOrNaNSpeedHoldsTheFrame)
{
    for (float badSpeed : {0.f, -1.f, std::numeric_limits<float>::quiet_NaN()})
    {
        Animation walk = threeFrameWalk();
        walk.setFrameSpeed(badSpeed);
        walk.animate(1.f);
        EXPECT_EQ(walk.getCurrentFrameIndex(), 0) << "speed " << badSpeed;
    }
}

TEST(Animation, TinySpeedAndHugeStepDoNotHang)
{
    Animation walk = threeFrameWalk();
    walk.setFrameSpeed(1e-30f);
    walk.animate(1e30f);
    EXPECT_GE(walk.getCurrentFrameIndex(), 0);
    EXPECT_LT(walk.getCurrentFrameIndex(), 3);
}

TEST(Animation, NegativeNaNOrInfiniteTimeIsIgnored)
{
    Animation walk = threeFrameWalk();
    walk.animate(-5.f);
    walk.animate(std::numeric_limits<float>::quiet_NaN());
    walk.animate(std::numeric_limits<float>::infinity());
    walk.animate(0.2f);
    EXPECT_EQ(walk.getCurrentFrameIndex(), 0);
    walk.animate(0.05f);
    EXPECT_EQ(walk.getCurrentFrameIndex(), 1);
}
