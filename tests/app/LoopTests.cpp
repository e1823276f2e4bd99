// The application loop's pieces that need no window: the fixed step, letterboxing, the
// command line, headless simulation.
#include "support/CommandLine.h"
#include "support/SfmlPrinters.h"

#include "hitbox/app/App.h"
#include "hitbox/app/FixedStep.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Loop.h"
#include "hitbox/sfml/Conversions.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

namespace
{

// A ball falling under gravity, bouncing on a floor: enough to show any frame-rate effect.
class FallingBallLevel : public hitbox::Level
{
public:
    void update(float dt) override
    {
        velocity += 980.f * dt;
        height += velocity * dt;
        if (height > 500.f)
        {
            height = 500.f;
            velocity = -velocity * 0.8f;
        }
        ++steps;
    }
    void render(sf::RenderTarget&) const override {}
    float height = 0.f;
    float velocity = 0.f;
    int steps = 0;
};

FallingBallLevel runAtFrameRate(const std::vector<float>& frameTimes)
{
    FallingBallLevel level;
    hitbox::FixedStep fixedStep(hitbox::stepSeconds);
    for (float frame : frameTimes)
    {
        const int steps = fixedStep.advance(frame);
        for (int i = 0; i < steps; ++i)
            level.update(hitbox::stepSeconds);
    }
    return level;
}

} // namespace

TEST(FixedStep, SameResultWhateverTheFrameRate)
{
    // Three seconds at 30 fps, at 144 fps, and at an uneven rate.
    const FallingBallLevel slow = runAtFrameRate(std::vector<float>(90, 1.f / 30.f));
    const FallingBallLevel fast = runAtFrameRate(std::vector<float>(432, 1.f / 144.f));
    std::vector<float> uneven;
    for (int i = 0; i < 200; ++i)
        uneven.push_back(i % 2 == 0 ? 0.005f : 0.025f);
    const FallingBallLevel jittery = runAtFrameRate(uneven);

    const int threeSeconds = static_cast<int>(3.f * hitbox::stepsPerSecond);
    EXPECT_EQ(slow.steps, threeSeconds);
    EXPECT_NEAR(fast.steps, threeSeconds, 1);
    EXPECT_NEAR(jittery.steps, threeSeconds, 1);
    // Same number of identical steps means the same state, exactly.
    const FallingBallLevel reference =
        runAtFrameRate(std::vector<float>(threeSeconds, hitbox::stepSeconds));
    EXPECT_EQ(slow.height, reference.height);
    EXPECT_EQ(slow.velocity, reference.velocity);
}

TEST(FixedStep, AStallIsCappedAndStepsStayShort)
{
    hitbox::FixedStep fixedStep(0.01f, 0.25f);
    // A 10-second breakpoint: at most a quarter of a second is simulated, in 0.01 s steps.
    EXPECT_EQ(fixedStep.advance(10.f), 25);
    EXPECT_EQ(fixedStep.advance(0.01f), 1);
}

TEST(FixedStep, ShortFramesSaveUpTime)
{
    hitbox::FixedStep fixedStep(0.01f);
    EXPECT_EQ(fixedStep.advance(0.004f), 0);
    EXPECT_EQ(fixedStep.advance(0.004f), 0);
    EXPECT_EQ(fixedStep.advance(0.004f), 1);
    EXPECT_NEAR(fixedStep.getLeftoverFraction(), 0.2f, 1e-3f);
}

TEST(FixedStep, NegativeAndNanFramesCountAsZero)
{
    hitbox::FixedStep fixedStep(0.01f);
    EXPECT_EQ(fixedStep.advance(-1.f), 0);
    EXPECT_EQ(fixedStep.advance(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(fixedStep.advance(0.01f), 1);
}

TEST(Letterbox, WideWindowGetsBarsLeftAndRight)
{
    const hitbox::Box viewport =
        hitbox::toBox(hitbox::letterboxViewport({2400, 675}, hitbox::defaultWorldSize));
    EXPECT_FLOAT_EQ(viewport.width, 0.5f);
    EXPECT_FLOAT_EQ(viewport.left, 0.25f);
    EXPECT_FLOAT_EQ(viewport.height, 1.f);
}

TEST(Letterbox, TallWindowGetsBarsAboveAndBelow)
{
    const hitbox::Box viewport =
        hitbox::toBox(hitbox::letterboxViewport({1200, 1350}, hitbox::defaultWorldSize));
    EXPECT_FLOAT_EQ(viewport.height, 0.5f);
    EXPECT_FLOAT_EQ(viewport.top, 0.25f);
}

TEST(Letterbox, SameAspectFillsTheWindowAndZeroSizeIsSafe)
{
    EXPECT_EQ(hitbox::letterboxViewport({600, 337}, {1200.f, 674.f}),
              sf::FloatRect({0, 0}, {1, 1}));
    EXPECT_EQ(hitbox::letterboxViewport({0, 0}, hitbox::defaultWorldSize),
              sf::FloatRect({0, 0}, {1, 1}));
}

TEST(CommandLine, SharedOptions)
{
    const hitbox::Options options =
        parseCommandLine({"--headless", "--frames", "42", "--seed", "7"});
    EXPECT_TRUE(options.headless);
    EXPECT_EQ(options.frames, 42);
    EXPECT_EQ(options.seed, 7u);
    EXPECT_EQ(parseCommandLine({"--seconds", "3"}).frames, 360);
    EXPECT_EQ(parseCommandLine({"--screenshot", "a.png", "--debug"}).screenshotPath, "a.png");
}

TEST(CommandLine, ProgramOptionsAndBadInputGetClearErrors)
{
    EXPECT_EQ(parseCommandLine({"--mode", "two"}, {"--mode"}).get("--mode", "one"), "two");
    EXPECT_EQ(parseCommandLine({}, {"--mode"}).get("--mode", "one"), "one");
    EXPECT_THROW(parseCommandLine({"--mode", "two"}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--frames"}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--frames", "ten"}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--frames", "-3"}), std::invalid_argument);
    EXPECT_THROW(parseCommandLine({"--headless", "--screenshot", "x.png"}), std::invalid_argument);
}

TEST(Simulate, RunsExactlyTheFramesAskedWithNoInput)
{
    FallingBallLevel level;
    hitbox::simulate(level, 240);
    EXPECT_EQ(level.steps, 240);
    EXPECT_GT(level.height, 0.f);
}

namespace
{
// A host whose frames take the given times; it writes down what the loop asks it to draw.
class ScriptedHost : public hitbox::LoopHost
{
public:
    explicit ScriptedHost(std::vector<float> frames) : frames(std::move(frames)) {}
    bool isRunning() const override { return next < frames.size(); }
    float secondsSinceLastFrame() override { return frames[next++]; }
    void processInput(hitbox::Input&) override { ++inputs; }
    int stepsToRun(int due) override { return due; }
    void render(const hitbox::Level& level, float leftover) override
    {
        const auto& ball = static_cast<const FallingBallLevel&>(level);
        drawn.push_back({ball.steps, leftover});
    }
    std::vector<float> frames;
    std::size_t next = 0;
    int inputs = 0;
    std::vector<std::pair<int, float>> drawn; // steps run so far, leftover fraction
};
} // namespace

TEST(Loop, InputThenTheDueStepsThenOneDrawingWithTheLeftoverFraction)
{
    // Frames of 0.4, 1.3 and 0.5 steps: 0, 1 and 1 steps run (0.4, 0.7 and 0.2 left over).
    const float step = hitbox::stepSeconds;
    ScriptedHost host({0.4f * step, 1.3f * step, 0.5f * step});
    FallingBallLevel level;
    hitbox::runLoop(level, host);
    EXPECT_EQ(host.inputs, 3);
    ASSERT_EQ(host.drawn.size(), 3u);
    const int steps[] = {0, 1, 2};
    const float leftovers[] = {0.4f, 0.7f, 0.2f};
    for (int frame = 0; frame < 3; ++frame)
    {
        EXPECT_EQ(host.drawn[frame].first, steps[frame]) << "frame " << frame;
        EXPECT_NEAR(host.drawn[frame].second, leftovers[frame], 1e-3f) << "frame " << frame;
    }
}
