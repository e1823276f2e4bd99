#include "hitbox/broadphase/SecondThread.h"

#include <utility>

namespace hitbox
{

SecondThread::SecondThread() : thread([this] { serve(); }) {}

SecondThread::~SecondThread()
{
    {
        std::unique_lock<std::mutex> lock(mutex);
        jobDone.wait(lock, [this] { return !busy; });
        stopping = true;
    }
    jobGiven.notify_one();
    thread.join();
}

void SecondThread::start(std::function<void()> newJob)
{
    {
        std::lock_guard<std::mutex> lock(mutex);
        job = std::move(newJob);
        busy = true;
        failure = nullptr;
    }
    jobGiven.notify_one();
}

void SecondThread::finish()
{
    std::exception_ptr thrown;
    {
        std::unique_lock<std::mutex> lock(mutex);
        jobDone.wait(lock, [this] { return !busy; });
        thrown = std::exchange(failure, nullptr);
    }
    if (thrown)
        std::rethrow_exception(thrown);
}

void SecondThread::serve()
{
    std::unique_lock<std::mutex> lock(mutex);
    for (;;)
    {
        jobGiven.wait(lock, [this] { return busy || stopping; });
        if (!busy) // stopping, with no job in hand
            return;
        std::function<void()> current = std::move(job);
        job = nullptr;
        lock.unlock();
        std::exception_ptr thrown;
        try
        {
            current();
        }
        catch (...)
        {
            thrown = std::current_exception();
        }
        lock.lock();
        failure = thrown;
        busy = false;
        jobDone.notify_one();
    }
}

} // namespace hitbox
