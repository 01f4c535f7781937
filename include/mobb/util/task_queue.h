// One background thread that runs tasks one at a time, in the order posted: work a thread hands off so as
// not to wait for it (the crowd's HDF5 record writer: compression, checksums and the kernel's writes
// beside the simulation), done in the same order as in place. No global state: each user owns its queue.
#pragma once
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace mobb::util {

class TaskQueue {
public:
    /// Starts the thread; at most `capacity` tasks wait (post() waits for room), so what they hold stays
    /// bounded. Throws std::invalid_argument when capacity < 1.
    explicit TaskQueue(std::size_t capacity);
    /// Runs the tasks still waiting (unless one threw), then stops the thread.
    ~TaskQueue();
    TaskQueue(const TaskQueue&) = delete;
    TaskQueue& operator=(const TaskQueue&) = delete;

    /// Queues `task`. Once a task throws, those after it are dropped, and post() and drain() rethrow its
    /// exception from then on.
    void post(std::function<void()> task);
    /// Returns once every task posted has run (the caller may then touch what they touch); rethrows as
    /// post() does.
    void drain();

private:
    void loop();

    std::mutex mutex_;
    std::condition_variable posted_, done_;  // a task came (or stop); a task was taken or finished
    std::deque<std::function<void()>> tasks_;
    std::size_t capacity_;
    bool running_ = false, stop_ = false;
    std::exception_ptr error_;
    std::thread thread_;  // last: started once the rest is set
};

}  // namespace mobb::util
