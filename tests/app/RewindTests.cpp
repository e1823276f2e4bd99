// Rewind (Rewind.h): any of the last kept steps can be shown again exactly, from snapshots (or a
// level built again) and the written-down input; rewinding never changes the run that follows.
#include "hitbox/app/App.h"
#include "hitbox/app/Input.h"
#include "hitbox/app/Rewind.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace
{

// Balls on a line that bounce off each other and the ends, pushed by the arrow keys: a state
// where one wrong step anywhere shows in every later one.
class PushLevel : public hitbox::Level
{
public:
    struct State : hitbox::LevelState
    {
        std::vector<float> x, v;
        std::size_t bytes() const override { return sizeof(State) + 8 * x.size(); }
    };

    PushLevel() : state(std::make_unique<State>())
    {
        for (int i = 0; i < 6; ++i)
        {
            state->x.push_back(50.f + 90.f * static_cast<float>(i));
            state->v.push_back(30.f * static_cast<float>(i % 3) - 20.f);
        }
    }
    void handleInput(const hitbox::Input& input, float dt) override
    {
        if (input.isKeyDown(sf::Keyboard::Key::Right))
            state->v[0] += 400.f * dt;
        if (input.isPressed(sf::Keyboard::Key::Left))
            state->v[5] -= 50.f;
    }
    void update(float dt) override
    {
        for (std::size_t i = 0; i < state->x.size(); ++i)
        {
            state->x[i] += state->v[i] * dt;
            if (state->x[i] < 0.f || state->x[i] > 600.f)
                state->v[i] = -state->v[i] * 0.9f;
        }
        for (std::size_t i = 0; i + 1 < state->x.size(); ++i)
            if (state->x[i + 1] - state->x[i] < 10.f)
                std::swap(state->v[i], state->v[i + 1]);
    }
    void render(sf::RenderTarget&) const override {}
    std::unique_ptr<hitbox::LevelState> saveState() const override
    {
        return std::make_unique<State>(*state);
    }
    void restoreState(const hitbox::LevelState& saved) override
    {
        *state = static_cast<const State&>(saved);
    }
    std::string bits() const
    {
        std::string text(reinterpret_cast<const char*>(state->x.data()), 4 * state->x.size());
        return text +
               std::string(reinterpret_cast<const char*>(state->v.data()), 4 * state->v.size());
    }

    std::unique_ptr<State> state;
};

// The keys of step `i`: changes every few steps, from a seed.
void scriptKeys(hitbox::Input& input, std::mt19937& random)
{
    std::uniform_int_distribution<int> roll(0, 9);
    const int r = roll(random);
    if (r == 0)
        input.setKeyDown(sf::Keyboard::Key::Right);
    if (r == 1)
        input.setKeyUp(sf::Keyboard::Key::Right);
    if (r == 2)
        input.setKeyDown(sf::Keyboard::Key::Left);
    if (r == 3)
        input.setKeyUp(sf::Keyboard::Key::Left);
}

// The same level with no saveState: the rewind has to build it again (RewindReplay.h).
class UnsavedPushLevel : public PushLevel
{
public:
    std::unique_ptr<hitbox::LevelState> saveState() const override { return nullptr; }
};

std::string shownBits(const hitbox::RewindLevel& rewind)
{
    return static_cast<const PushLevel&>(rewind.shownLevel()).bits();
}

void liveStep(hitbox::Level& level, hitbox::Input& input)
{
    level.handleInput(input, hitbox::stepSeconds);
    level.update(hitbox::stepSeconds);
    input.update();
}

} // namespace

TEST(Rewind, EveryKeptStepIsShownExactlyAndTheRunGoesOnUnchanged)
{
    const long long kept = 200;
    const long long every = 25;
    PushLevel reference;
    PushLevel rewound;
    hitbox::RewindLevel rewind(rewound, kept, every);
    ASSERT_TRUE(rewind.canRewind());
    std::vector<std::string> history{reference.bits()};
    hitbox::Input referenceInput;
    hitbox::Input input;
    std::mt19937 referenceRandom(5);
    std::mt19937 random(5);
    for (int i = 0; i < 700; ++i)
    {
        scriptKeys(referenceInput, referenceRandom);
        liveStep(reference, referenceInput);
        history.push_back(reference.bits());
        scriptKeys(input, random);
        liveStep(rewind, input);
        if (i == 300 || i == 650)
        {
            // Paused: back through every kept step, then forward again, then jumps.
            EXPECT_EQ(rewind.oldestStep(), rewind.newestStep() - kept);
            for (long long at = rewind.newestStep(); at >= rewind.oldestStep(); --at)
            {
                ASSERT_EQ(rewind.show(at), at);
                ASSERT_EQ(rewound.bits(), history[static_cast<std::size_t>(at)]) << "step " << at;
            }
            for (long long at :
                 {rewind.oldestStep() + 7, rewind.newestStep() - 1, rewind.oldestStep() + 99})
            {
                rewind.show(at);
                ASSERT_EQ(rewound.bits(), history[static_cast<std::size_t>(at)]) << "step " << at;
            }
            EXPECT_EQ(rewind.show(0), rewind.oldestStep()) << "older steps are not kept";
        }
    }
    // Rewinding left the run as it was: the live state is the reference's, bit for bit.
    EXPECT_EQ(rewound.bits(), reference.bits());
    EXPECT_NE(history[100], history[700]) << "the scene should have moved";
}

TEST(Rewind, MemoryStaysBoundedHoweverLongTheRun)
{
    PushLevel level;
    hitbox::RewindLevel rewind(level, 120, 30);
    hitbox::Input input;
    std::size_t most = 0;
    for (int i = 0; i < 5000; ++i)
    {
        input.setKeyDown(sf::Keyboard::Key::Right);
        liveStep(rewind, input);
        if (i > 1000)
            most = std::max(most, rewind.bytesUsed());
    }
    const std::size_t snapshotBytes = level.saveState()->bytes() + sizeof(long long);
    // At most 120 / 30 + 2 snapshots and 120 + 30 inputs, whatever the run's length.
    EXPECT_LE(most, 6 * snapshotBytes + 150 * (sizeof(hitbox::InputSnapshot) + 3 * sizeof(int)));
    EXPECT_GE(most, 4 * snapshotBytes);
}

TEST(Rewind, ALevelThatCanNeitherBeSavedNorBuiltAgainIsNeverRewound)
{
    class Plain : public hitbox::Level
    {
    public:
        void update(float) override { ++steps; }
        void render(sf::RenderTarget&) const override {}
        int steps = 0;
    } plain;
    hitbox::RewindLevel rewind(plain);
    hitbox::simulate(rewind, 10);
    EXPECT_FALSE(rewind.canRewind());
    EXPECT_EQ(rewind.show(3), 10);
    EXPECT_EQ(plain.steps, 10);
    EXPECT_EQ(rewind.bytesUsed(), 0u);
}

TEST(Rewind, ALevelThatCannotBeSavedIsBuiltAgainAndShownExactly)
{
    const long long kept = 200;
    PushLevel reference;
    UnsavedPushLevel live;
    hitbox::RewindLevel rewind(
        live, [] { return std::make_unique<UnsavedPushLevel>(); }, kept);
    ASSERT_TRUE(rewind.canRewind());
    ASSERT_TRUE(rewind.rebuilds());
    std::vector<std::string> history{reference.bits()};
    hitbox::Input referenceInput;
    hitbox::Input input;
    std::mt19937 referenceRandom(8);
    std::mt19937 random(8);
    for (int i = 0; i < 600; ++i)
    {
        scriptKeys(referenceInput, referenceRandom);
        liveStep(reference, referenceInput);
        history.push_back(reference.bits());
        scriptKeys(input, random);
        liveStep(rewind, input);
        ASSERT_EQ(shownBits(rewind), history.back()) << "live step " << i + 1;
        if (i != 250 && i != 550)
            continue;
        EXPECT_EQ(rewind.oldestStep(), rewind.newestStep() - kept);
        for (long long at = rewind.newestStep(); at >= rewind.oldestStep(); --at)
        {
            ASSERT_EQ(rewind.show(at), at);
            ASSERT_EQ(shownBits(rewind), history[static_cast<std::size_t>(at)]) << "step " << at;
            // Looking back never touches the running level.
            ASSERT_EQ(live.bits(), history.back());
        }
        for (long long at = rewind.oldestStep(); at <= rewind.newestStep(); ++at)
        {
            rewind.show(at);
            ASSERT_EQ(shownBits(rewind), history[static_cast<std::size_t>(at)]) << "step " << at;
        }
        // What a key press costs: one step forward is one step; one step back from step t is
        // t - 1 steps from the start.
        const long long t = rewind.newestStep() - 50;
        rewind.show(t);
        long long before = rewind.stepsReplayed();
        rewind.show(t + 1);
        EXPECT_EQ(rewind.stepsReplayed() - before, 1);
        before = rewind.stepsReplayed();
        rewind.show(t);
        EXPECT_EQ(rewind.stepsReplayed() - before, t);
    }
    EXPECT_EQ(live.bits(), reference.bits());
    EXPECT_NE(history[100], history[600]) << "the scene should have moved";
}

TEST(Rewind, ARebuiltLevelKeepsOnlyTheInputRowsThatChanged)
{
    UnsavedPushLevel live;
    hitbox::RewindLevel rewind(live, [] { return std::make_unique<UnsavedPushLevel>(); });
    hitbox::Input input;
    input.setKeyDown(sf::Keyboard::Key::Right);
    for (int i = 0; i < 5000; ++i)
        liveStep(rewind, input);
    const std::size_t steady = rewind.bytesUsed();
    EXPECT_LE(steady, 1024u) << "5,000 steps of one held key: two input rows";
    for (int i = 0; i < 100; ++i)
    {
        input.setMousePosition({static_cast<float>(i), 0.f}); // a new row every step
        liveStep(rewind, input);
    }
    EXPECT_GE(rewind.bytesUsed(), steady + 100 * sizeof(hitbox::InputSnapshot));
}

TEST(Rewind, ARebuiltLevelStopsRewindingAtItsMemoryBound)
{
    UnsavedPushLevel live;
    const long long bound = 600;
    hitbox::RewindLevel rewind(
        live, [] { return std::make_unique<UnsavedPushLevel>(); }, hitbox::rewindSteps,
        hitbox::rewindSnapshotSteps, bound);
    hitbox::Input input;
    for (long long i = 0; i < bound; ++i)
    {
        input.setMousePosition({static_cast<float>(i), 0.f}); // a new row every step
        liveStep(rewind, input);
    }
    ASSERT_TRUE(rewind.canRewind()) << "within the bound, the rebuilt level rewinds";
    EXPECT_EQ(rewind.show(bound - 10), bound - 10);
    const std::size_t atBound = rewind.bytesUsed();
    for (long long i = 0; i < 2 * bound; ++i)
    {
        input.setMousePosition({static_cast<float>(i), 1.f});
        liveStep(rewind, input);
    }
    EXPECT_FALSE(rewind.canRewind()) << "past the bound, the input rows are let go";
    EXPECT_LT(rewind.bytesUsed(), atBound);
    EXPECT_EQ(rewind.show(10), rewind.newestStep()) << "nothing earlier is shown";
    EXPECT_EQ(shownBits(rewind), live.bits());
}
