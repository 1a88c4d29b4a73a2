#include "support/thread_pool.hpp"

#include <chrono>

namespace obbsat::detail {

namespace {

// How long a worker keeps polling for the next batch, and the caller for the
// end of this one, before sleeping.
constexpr std::chrono::microseconds worker_spin{500};
constexpr std::chrono::microseconds caller_spin{2000};

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// Polls `done` until it holds or `budget` has passed; true if it holds.
template <class Done>
bool spin_until(const Done& done, std::chrono::microseconds budget) {
    const auto deadline = std::chrono::steady_clock::now() + budget;
    for (unsigned k = 0;; ++k) {
        if (done()) {
            return true;
        }
        if ((k & 63u) == 0 && std::chrono::steady_clock::now() > deadline) {
            return done();
        }
        relax();
    }
}

// True on a thread while it runs a part of a batch (a worker, always; the
// caller, during its part 0). A run started there runs its parts in turn on
// that thread: the workers are busy with the batch that holds the pool, and
// the caller would otherwise try to take batch_owner_, which it already holds.
thread_local bool running_a_part = false;

}  // namespace

thread_pool& thread_pool::shared() {
    static thread_pool pool;
    return pool;
}

thread_pool::~thread_pool() {
    {
        std::lock_guard<std::mutex> lock(state_);
        stopping_.store(true, std::memory_order_release);
    }
    wake_.notify_all();
    for (auto& w : workers_) {
        w.join();
    }
}

void thread_pool::grow_to(std::size_t workers) {
    while (workers_.size() < workers) {
        const std::size_t part = workers_.size() + 1;  // part 0 is the caller's
        workers_.emplace_back([this, part] { worker_loop(part); });
    }
}

void thread_pool::worker_loop(std::size_t part) {
    running_a_part = true;
    std::uint64_t seen = 0;
    for (;;) {
        auto new_batch = [&] {
            return stopping_.load(std::memory_order_acquire) ||
                   generation_.load(std::memory_order_acquire) != seen;
        };
        if (!spin_until(new_batch, worker_spin)) {
            std::unique_lock<std::mutex> lock(state_);
            wake_.wait(lock, new_batch);
        }
        if (stopping_.load(std::memory_order_acquire)) {
            return;
        }
        seen = generation_.load(std::memory_order_acquire);
        if (part >= parts_.load(std::memory_order_relaxed)) {
            continue;
        }
        (*task_.load(std::memory_order_relaxed))(part);
        if (unfinished_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            // Taking the lock orders this notify after a caller that found
            // work unfinished has started waiting: no wake-up is lost.
            std::lock_guard<std::mutex> lock(state_);
            finished_.notify_one();
        }
    }
}

void thread_pool::run(std::size_t parts, const std::function<void(std::size_t)>& task) {
    std::unique_lock<std::mutex> owner;
    if (parts > 1 && !running_a_part) {
        owner = std::unique_lock<std::mutex>(batch_owner_, std::try_to_lock);
    }
    if (!owner.owns_lock()) {
        for (std::size_t p = 0; p < parts; ++p) {
            task(p);
        }
        return;
    }
    {
        std::lock_guard<std::mutex> lock(state_);
        grow_to(parts - 1);
        task_.store(&task, std::memory_order_relaxed);
        parts_.store(parts, std::memory_order_relaxed);
        unfinished_.store(parts - 1, std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    running_a_part = true;
    task(0);
    running_a_part = false;
    auto all_done = [&] { return unfinished_.load(std::memory_order_acquire) == 0; };
    if (!spin_until(all_done, caller_spin)) {
        std::unique_lock<std::mutex> lock(state_);
        finished_.wait(lock, all_done);
    }
}

}  // namespace obbsat::detail
