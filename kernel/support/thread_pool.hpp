// A persistent pool of worker threads, so that splitting a batch over cores
// costs a wake-up, not a thread start.
//
// A worker is never waited for unless it has joined the batch: the parts are
// taken from a shared counter by the caller and by the workers that join
// while the caller is still taking them. Once the caller finds no part left,
// it closes the batch (a worker that comes later leaves it alone) and waits
// only for the parts that joined workers are running. So a worker on a core
// busy with other work, not yet given the core when the batch starts, costs
// the caller nothing: the caller runs its parts instead.
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

    /// Runs task(0) .. task(parts - 1), each once, and returns when all have
    /// finished. The calling thread runs part 0, then takes the next part not
    /// taken, as do up to parts - 1 workers that join in time; with no worker
    /// joining, the caller runs them all. If another batch holds the pool, or
    /// the call comes from inside a part of a batch, the parts run one after
    /// another on the calling thread. `task` must not throw.
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
    /// Times, since the pool started, that a worker came to a batch the caller had closed.
    std::uint64_t late_arrivals() const { return late_arrivals_.load(); }

    ~thread_pool();

private:
    struct worker {
        std::thread thread;
        std::condition_variable wake;  ///< notified when a batch gives this worker a part
        bool asleep = false;           ///< waiting on `wake`; under state_
        std::atomic<int> cpu{-2};      ///< its CPU when it joined this batch; -2 before, -1 unknown
    };

    thread_pool() = default;
    void grow_to(std::size_t workers);
    void worker_loop(worker& self, std::size_t slot, std::uint64_t seen);
    /// Joins the batch of `generation` unless it is closed or over; true if joined.
    bool join(std::uint64_t generation);
    /// Runs parts from the shared counter until none is left.
    void take_parts(const std::function<void(std::size_t)>& task, std::size_t parts);

    std::mutex batch_owner_;  // held by the one batch using the workers
    mutable std::mutex state_;
    std::condition_variable finished_;
    std::vector<std::unique_ptr<worker>> workers_;
    // The batch: its generation in the high 32 bits, its parts in the low 32,
    // one word so that a worker reads both of the same batch. Written after
    // task_, next_part_, left_ and entry_ (release), read by a worker before
    // them (acquire).
    std::atomic<std::uint64_t> batch_{0};
    // Who joined the batch: its generation in the high 32 bits, bit 31 set
    // once the caller has closed it, the workers that joined in the low 31.
    std::atomic<std::uint64_t> entry_{0};
    std::atomic<const std::function<void(std::size_t)>*> task_{nullptr};
    std::atomic<std::size_t> next_part_{0};  ///< the next part not taken
    std::atomic<std::size_t> left_{0};       ///< joined workers that have taken their last part
    std::atomic<int> caller_cpu_{-1};        ///< the caller's CPU when it started the last batch
    std::atomic<bool> stopping_{false};
    std::atomic<std::size_t> awake_{0};
    std::atomic<std::uint64_t> polls_started_{0};
    std::atomic<std::uint64_t> wake_ups_{0};
    std::atomic<std::uint64_t> late_arrivals_{0};
};

}  // namespace obbsat::detail
