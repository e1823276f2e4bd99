// SecondThread.h - one helper thread, started once, that runs the jobs handed to it one at a
// time and sleeps in between. The grid's two halves use it for every pass of every frame:
// starting a std::thread per pass cost 36 us of a frame on Linux here and 1.4 ms under wine
// (docs/performance.md).
#pragma once

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace hitbox
{

class SecondThread
{
public:
    // Starts the thread; throws std::system_error if the system cannot start one.
    SecondThread();
    // Waits for the job in hand, if any, then stops the thread.
    ~SecondThread();
    SecondThread(const SecondThread&) = delete;
    SecondThread& operator=(const SecondThread&) = delete;

    // Runs `job` on the helper thread while the caller goes on. One job at a time: call
    // finish() before the next start().
    void start(std::function<void()> job);
    // Returns once the job from start() has run; rethrows what it threw. At once without a job.
    void finish();

private:
    void serve();

    std::mutex mutex;
    std::condition_variable jobGiven;
    std::condition_variable jobDone;
    std::function<void()> job; // empty: nothing to run
    bool busy = false;         // a job was given and has not finished
    bool stopping = false;
    std::exception_ptr failure; // what the last job threw
    std::thread thread;         // last: started once the fields above exist
};

} // namespace hitbox
