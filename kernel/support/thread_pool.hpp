// A persistent pool of worker threads, so that splitting a batch over cores
// costs a wake-up, not a thread start.
//
// Workers and the caller spin briefly on atomics before sleeping on condition
// variables: waking a sleeping thread takes tens to hundreds of microseconds
// on a virtual machine, a large share of a batch of a few hundred thousand
// pairs, while back-to-back batches (a frame loop, a benchmark) find the
// workers still spinning.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace obbsat::detail {

class thread_pool {
public:
    /// The process-wide pool; workers start on first use and live until exit.
    static thread_pool& shared();

    /// Runs task(0) .. task(parts - 1) and returns when all have finished. The
    /// calling thread runs part 0. If another batch holds the pool, or the
    /// call comes from inside a part of a batch, the parts run one after
    /// another on the calling thread. `task` must not throw.
    void run(std::size_t parts, const std::function<void(std::size_t)>& task);

    ~thread_pool();

private:
    thread_pool() = default;
    void grow_to(std::size_t workers);
    void worker_loop(std::size_t part);

    std::mutex batch_owner_;  // held by the one batch using the workers
    std::mutex state_;
    std::condition_variable wake_;
    std::condition_variable finished_;
    std::vector<std::thread> workers_;
    // Written before generation_ is advanced (release), read by a worker after
    // it sees the new generation (acquire); atomic because a worker with no
    // part in a batch may still be reading them when the next batch starts.
    std::atomic<const std::function<void(std::size_t)>*> task_{nullptr};
    std::atomic<std::size_t> parts_{0};
    std::atomic<std::size_t> unfinished_{0};
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<bool> stopping_{false};
};

}  // namespace obbsat::detail
