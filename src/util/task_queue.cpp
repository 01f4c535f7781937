#include "mobb/util/task_queue.h"

#include <stdexcept>
#include <utility>

namespace mobb::util {

TaskQueue::TaskQueue(std::size_t capacity) : capacity_(capacity) {
    if (capacity < 1) throw std::invalid_argument("task queue: room for at least one task expected");
    thread_ = std::thread([this] { loop(); });
}

TaskQueue::~TaskQueue() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    posted_.notify_one();
    thread_.join();
}

void TaskQueue::post(std::function<void()> task) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return error_ || tasks_.size() < capacity_; });
    if (error_) std::rethrow_exception(error_);
    tasks_.push_back(std::move(task));
    lock.unlock();
    posted_.notify_one();
}

void TaskQueue::drain() {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return error_ || (tasks_.empty() && !running_); });
    if (error_) std::rethrow_exception(error_);
}

void TaskQueue::loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        posted_.wait(lock, [&] { return stop_ || !tasks_.empty(); });
        if (tasks_.empty()) return;  // stopped, and nothing left to run
        std::function<void()> task = std::move(tasks_.front());
        tasks_.pop_front();
        running_ = true;
        lock.unlock();
        done_.notify_all();  // room for another
        std::exception_ptr error;
        try {
            task();
        } catch (...) {
            error = std::current_exception();
        }
        task = nullptr;  // what it holds goes here, outside the lock
        lock.lock();
        running_ = false;
        if (error && !error_) error_ = error;
        if (error_) tasks_.clear();
        done_.notify_all();
    }
}

}  // namespace mobb::util
