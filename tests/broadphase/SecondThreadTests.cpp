// SecondThread: the grid's kept helper thread runs each job once, on its own thread, and
// hands back what the job threw; the grid's two-thread results are checked in
// AgreementTests.cpp and RulesTests.cpp.
#include "hitbox/broadphase/SecondThread.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace
{

TEST(SecondThread, RunsTheJobOnItsOwnThreadAndFinishWaitsForIt)
{
    hitbox::SecondThread helper;
    std::thread::id ranOn;
    int result = 0;
    helper.start(
        [&]
        {
            ranOn = std::this_thread::get_id();
            result = 42;
        });
    helper.finish();
    EXPECT_EQ(result, 42);
    EXPECT_NE(ranOn, std::this_thread::get_id());
}

TEST(SecondThread, RunsEveryJobOnceInTurnOnTheSameThread)
{
    hitbox::SecondThread helper;
    int runs = 0;
    std::thread::id firstThread;
    bool sameThread = true;
    for (int job = 0; job < 1000; ++job)
    {
        helper.start(
            [&, job]
            {
                if (job == 0)
                    firstThread = std::this_thread::get_id();
                sameThread = sameThread && std::this_thread::get_id() == firstThread;
                ++runs;
            });
        helper.finish();
        ASSERT_EQ(runs, job + 1);
    }
    EXPECT_TRUE(sameThread); // started once, not once per job
}

TEST(SecondThread, FinishRethrowsWhatTheJobThrewAndTheNextJobStillRuns)
{
    hitbox::SecondThread helper;
    helper.start([] { throw std::runtime_error("out of memory in a half"); });
    EXPECT_THROW(helper.finish(), std::runtime_error);
    bool ran = false;
    helper.start([&] { ran = true; });
    EXPECT_NO_THROW(helper.finish());
    EXPECT_TRUE(ran);
}

TEST(SecondThread, FinishWithoutAJobReturnsAtOnce)
{
    hitbox::SecondThread helper;
    EXPECT_NO_THROW(helper.finish());
}

TEST(SecondThread, StoppingWaitsForTheJobInHand)
{
    std::atomic<bool> done{false};
    {
        hitbox::SecondThread helper;
        helper.start(
            [&]
            {
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
                done = true;
            });
    } // no finish(): the destructor waits
    EXPECT_TRUE(done);
}

} // namespace
