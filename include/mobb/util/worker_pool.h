// A small persistent pool of worker threads for data-parallel loops: the crowd's choice points of one
// frame (paper section 5) and `mobb batch` queries. No global state: each user owns its pool.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace mobb::util {

class WorkerPool {
public:
    /// A pool of `threads` workers; the calling thread is worker 0, so one worker starts no thread.
    /// Throws std::invalid_argument when threads < 1.
    explicit WorkerPool(int threads);
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int size() const { return int(threads_.size()) + 1; }

    /// Calls f(index, worker) once for every index in [0, n), indices handed out in chunks of `grain`
    /// to workers 0 .. size() - 1, and returns when every call has returned. Which worker runs which
    /// index is not deterministic; callers write results by index. If calls throw, the exception of
    /// the lowest index is rethrown after all calls finished. Not reentrant: call from one thread; a call
    /// made before the last returned (from f, or from another thread) throws std::logic_error.
    void for_each(std::size_t n, const std::function<void(std::size_t, int)>& f, std::size_t grain = 1);

    /// Calls of for_each() handed to the workers so far (more than one chunk, on a pool of more than one
    /// thread): each a wake and a wait on every thread. None on one thread.
    std::uint64_t steps() const { return steps_; }

    /// std::thread::hardware_concurrency(), at least 1.
    static int hardware_threads();

private:
    // The pool's one job (for_each is not reentrant). Workers join it without a lock: a worker that sees
    // generation g open counts itself `inside`, then checks g is still open; the caller closes the job
    // (posted_ = kClosed) and waits for `inside` to reach 0 before it sets up the next one (Dekker's check,
    // sequentially consistent). Workers that join late find no index left.
    struct Job {
        const std::function<void(std::size_t, int)>* f = nullptr;
        std::size_t n = 0, grain = 1;
        std::atomic<std::size_t> next{0}, finished{0};
        std::atomic<int> inside{0};
        std::exception_ptr error;  // guarded by the pool's mutex
        std::size_t error_index = 0;
    };
    static constexpr std::uint64_t kClosed = 0;

    void loop(int worker);
    void join(int worker, std::uint64_t& seen);
    void open(std::size_t n, const std::function<void(std::size_t, int)>& f, std::size_t grain);
    void work(int worker);

    std::vector<std::thread> threads_;
    std::mutex mutex_;  // for sleeping and waking, and a job's error
    std::condition_variable start_, done_;
    Job job_;
    std::uint64_t generation_ = kClosed;          // the latest job's
    std::atomic<std::uint64_t> posted_{kClosed};  // the job workers may join, or kClosed
    std::atomic<int> sleepers_{0};                // workers waiting on start_
    std::atomic<bool> stop_{false};
    std::atomic<bool> busy_{false};  // a for_each is running
    std::uint64_t steps_ = 0;
};

}  // namespace mobb::util
