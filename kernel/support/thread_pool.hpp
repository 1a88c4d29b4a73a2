// A persistent pool of worker threads, so that splitting a batch over cores
// costs a wake-up, not a thread start.
//
// A worker that has just run a part polls briefly for the next batch before
// sleeping: waking a sleeping thread takes tens to hundreds of microseconds on
// a virtual machine, a large share of a step of a few hundred thousand boxes,
// while back-to-back steps (the scene query's, a frame loop) find it still
// polling. A worker with no part in a batch is not woken for it, and one that
// had no part in the last batch sleeps at once: a run on 64 threads leaves no
// spinning behind for the runs on 2 that follow. The caller polls for the end
// of its batch a little longer before it sleeps too.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace obbsat::detail {

class thread_pool {
public:
    /// The process-wide pool; workers start on first use and live until exit.
    static thread_pool& shared();

    /// Runs task(0) .. task(parts - 1) and returns when all have finished. The
    /// calling thread runs part 0, worker k - 1 part k. If another batch holds
    /// the pool, or the call comes from inside a part of a batch, the parts
    /// run one after another on the calling thread. `task` must not throw.
    void run(std::size_t parts, const std::function<void(std::size_t)>& task);

    // What the workers are doing, for tests (tests/support/test_thread_pool.cpp).
    /// Workers started so far.
    std::size_t workers() const;
    /// Workers not asleep: running a part or polling for the next batch.
    std::size_t awake_workers() const { return awake_.load(); }
    /// Times, since the pool started, that a worker began to poll for a batch.
    std::uint64_t polls_started() const { return polls_started_.load(); }
    /// Times, since the pool started, that a sleeping worker woke for a batch.
    std::uint64_t wake_ups() const { return wake_ups_.load(); }

    ~thread_pool();

private:
    struct worker {
        std::thread thread;
        std::condition_variable wake;  ///< notified when a batch gives this worker a part
        bool asleep = false;           ///< waiting on `wake`; under state_
    };

    thread_pool() = default;
    void grow_to(std::size_t workers);
    void worker_loop(worker& self, std::size_t part, std::uint64_t seen);

    std::mutex batch_owner_;  // held by the one batch using the workers
    mutable std::mutex state_;
    std::condition_variable finished_;
    std::vector<std::unique_ptr<worker>> workers_;
    // The batch: its generation in the high 32 bits, its parts in the low 32,
    // one word so that a worker reads both of the same batch. Written after
    // task_ and unfinished_ (release), read by a worker before them (acquire).
    std::atomic<std::uint64_t> batch_{0};
    std::atomic<const std::function<void(std::size_t)>*> task_{nullptr};
    std::atomic<std::size_t> unfinished_{0};
    std::atomic<bool> stopping_{false};
    std::atomic<std::size_t> awake_{0};
    std::atomic<std::uint64_t> polls_started_{0};
    std::atomic<std::uint64_t> wake_ups_{0};
};

}  // namespace obbsat::detail
