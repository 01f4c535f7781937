#include "mobb/util/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace {

// A crowd frame's parallel loops come up to a few milliseconds apart (the serial commits between
// them), and a thread woken from sleep joins a loop late, often after it ended: spin this long first.
// (With 300 us the check for stale choice points, a loop of ~0.1 ms per frame at 10,000 agents, ran
// no faster on 2 threads than on 1.)
constexpr auto kSpin = std::chrono::microseconds(3000);

template <class Ready>
bool spin_until(Ready&& ready) {
    const auto end = std::chrono::steady_clock::now() + kSpin;
    for (int k = 0;; ++k) {
        if (ready()) return true;
        if ((k & 63) == 63 && std::chrono::steady_clock::now() > end) return false;
        std::this_thread::yield();
    }
}

}  // namespace

namespace mobb::util {

WorkerPool::WorkerPool(int threads) {
    if (threads < 1) throw std::invalid_argument("worker pool: at least one thread expected");
    for (int w = 1; w < threads; ++w) threads_.emplace_back([this, w] { loop(w); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

int WorkerPool::hardware_threads() { return std::max(1, int(std::thread::hardware_concurrency())); }

void WorkerPool::for_each(std::size_t n, const std::function<void(std::size_t, int)>& f, std::size_t grain) {
    if (n == 0) return;
    auto job = std::make_shared<Job>();
    job->f = &f;
    job->n = n;
    job->grain = std::max<std::size_t>(1, grain);
    // A single chunk is not worth waking anybody (a frame with one choice point is common).
    if (!threads_.empty() && n > job->grain) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            job_ = job;
            posted_.store(++generation_, std::memory_order_release);
        }
        start_.notify_all();
    }
    work(*job, 0);
    if (!spin_until([&] { return job->finished.load() == n; })) {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [&] { return job->finished.load() == n; });
    }
    if (job->error) std::rethrow_exception(job->error);
}

void WorkerPool::loop(int worker) {
    std::uint64_t seen = 0;
    for (;;) {
        std::shared_ptr<Job> job;
        spin_until([&] { return posted_.load(std::memory_order_acquire) != seen; });
        {
            std::unique_lock<std::mutex> lock(mutex_);
            start_.wait(lock, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
            job = job_;
        }
        work(*job, worker);
    }
}

// Claims chunks until none is left. f is called only for a claimed index, which the caller of
// for_each still waits for, so f is alive then.
void WorkerPool::work(Job& job, int worker) {
    for (;;) {
        const std::size_t first = job.next.fetch_add(job.grain);
        if (first >= job.n) return;
        const std::size_t last = std::min(job.n, first + job.grain);
        for (std::size_t i = first; i < last; ++i) {
            try {
                (*job.f)(i, worker);
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex_);
                if (!job.error || i < job.error_index) {
                    job.error = std::current_exception();
                    job.error_index = i;
                }
            }
        }
        if (job.finished.fetch_add(last - first) + (last - first) == job.n) {
            std::lock_guard<std::mutex> lock(mutex_);  // so the caller cannot miss the wake-up
            done_.notify_all();
        }
    }
}

}  // namespace mobb::util
