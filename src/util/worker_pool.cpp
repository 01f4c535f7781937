#include "mobb/util/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

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
    stop_ = true;
    { std::lock_guard<std::mutex> lock(mutex_); }  // a worker between its check and its wait gets the wake
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

int WorkerPool::hardware_threads() { return std::max(1, int(std::thread::hardware_concurrency())); }

void WorkerPool::for_each(std::size_t n, const std::function<void(std::size_t, int)>& f, std::size_t grain) {
    if (n == 0) return;
    if (busy_.exchange(true)) throw std::logic_error("worker pool: for_each called again before it returned");
    open(n, f, grain);
    work(0);
    const auto done = [&] { return job_.finished.load() == n; };
    if (!spin_until(done)) {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, done);
    }
    busy_ = false;
    if (job_.error) std::rethrow_exception(std::exchange(job_.error, nullptr));
}

// Closes the last job, waits until no worker is inside it, sets up the next and, unless it is a single
// chunk (a frame with one choice point is common: not worth waking anybody), opens it to the workers.
void WorkerPool::open(std::size_t n, const std::function<void(std::size_t, int)>& f, std::size_t grain) {
    posted_ = kClosed;
    while (job_.inside.load() != 0) std::this_thread::yield();  // a worker that joined late leaves at once
    job_.f = &f;
    job_.n = n;
    job_.grain = std::max<std::size_t>(1, grain);
    job_.next = 0;
    job_.finished = 0;
    if (threads_.empty() || n <= job_.grain) return;
    ++steps_;
    posted_ = ++generation_;
    if (sleepers_.load() > 0) {
        { std::lock_guard<std::mutex> lock(mutex_); }
        start_.notify_all();
    }
}

void WorkerPool::loop(int worker) {
    std::uint64_t seen = kClosed;
    const auto ready = [&] {
        const std::uint64_t g = posted_.load();
        return stop_.load() || (g != kClosed && g != seen);
    };
    while (!stop_.load()) {
        if (!spin_until(ready)) {
            std::unique_lock<std::mutex> lock(mutex_);
            ++sleepers_;
            start_.wait(lock, ready);
            --sleepers_;
        }
        if (!stop_.load()) join(worker, seen);
    }
}

// Joins the open job if it is still the one seen open: counted inside first, so the caller cannot set up
// the next job under it.
void WorkerPool::join(int worker, std::uint64_t& seen) {
    const std::uint64_t g = posted_.load();
    if (g == kClosed || g == seen) return;
    ++job_.inside;
    if (posted_.load() == g) {
        seen = g;
        work(worker);
    }
    --job_.inside;
}

// Claims chunks until none is left. f is called only for a claimed index, which the caller of
// for_each still waits for, so f is alive then.
void WorkerPool::work(int worker) {
    Job& job = job_;
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
