#include "support/thread_pool.hpp"

#include <chrono>
#include <limits>

#if defined(__linux__)
#include <sched.h>
#endif

namespace obbsat::detail {

namespace {

// How long a worker that has just run a part keeps polling for the next
// batch, and the caller for the end of this one, before sleeping.
constexpr std::chrono::microseconds worker_poll{300};
constexpr std::chrono::microseconds caller_poll{2000};

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

// The CPU this thread runs on, or -1 where the system does not say.
int current_cpu() {
#if defined(__linux__)
    return sched_getcpu();
#else
    return -1;
#endif
}

// Polls `done` until it holds or `budget` has passed; true if it holds. Every
// few dozen polls it yields if `on_shared_cpu()` says the thread it waits for
// (or works beside) runs on this one's CPU: the poll then hands that thread
// the CPU instead of taking it. It does not yield otherwise: on a CPU shared
// with a process of its own (a busy core), a yield gives that process the
// CPU for a whole time slice, long after what the poll waits for is done.
template <class Done, class OnSharedCpu>
bool poll_until(const Done& done, std::chrono::microseconds budget, const OnSharedCpu& on_shared_cpu) {
    const auto deadline = std::chrono::steady_clock::now() + budget;
    for (unsigned k = 1;; ++k) {
        if (done()) {
            return true;
        }
        if ((k & 63u) == 0) {
            if (std::chrono::steady_clock::now() > deadline) {
                return done();
            }
            if (on_shared_cpu()) {
                std::this_thread::yield();
            }
        }
        relax();
    }
}

constexpr std::uint64_t generation_of(std::uint64_t batch) { return batch >> 32; }
constexpr std::uint64_t parts_of(std::uint64_t batch) { return batch & 0xffffffffu; }
// In entry_: the batch closed to workers not yet in it, and how many are.
constexpr std::uint64_t closed_bit = std::uint64_t{1} << 31;
constexpr std::uint64_t joined_mask = closed_bit - 1;

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
        for (auto& w : workers_) {
            w->wake.notify_one();
        }
    }
    for (auto& w : workers_) {
        w->thread.join();
    }
}

std::size_t thread_pool::workers() const {
    std::lock_guard<std::mutex> lock(state_);
    return workers_.size();
}

void thread_pool::grow_to(std::size_t workers) {
    // Under state_, before the next batch is published: a new worker has
    // seen every batch so far, none of which had a part for it.
    const std::uint64_t seen = generation_of(batch_.load(std::memory_order_relaxed));
    while (workers_.size() < workers) {
        const std::size_t slot = workers_.size() + 1;  // invited to batches of more parts than this
        workers_.push_back(std::make_unique<worker>());
        worker& w = *workers_.back();
        awake_.fetch_add(1);
        w.thread = std::thread([this, &w, slot, seen] { worker_loop(w, slot, seen); });
    }
}

bool thread_pool::join(std::uint64_t generation) {
    std::uint64_t entry = entry_.load(std::memory_order_acquire);
    while (generation_of(entry) == generation && (entry & closed_bit) == 0) {
        if (entry_.compare_exchange_weak(entry, entry + 1, std::memory_order_acq_rel, std::memory_order_acquire)) {
            return true;
        }
    }
    return false;
}

void thread_pool::take_parts(const std::function<void(std::size_t)>& task, std::size_t parts) {
    for (std::size_t part = next_part_.fetch_add(1, std::memory_order_relaxed); part < parts;
         part = next_part_.fetch_add(1, std::memory_order_relaxed)) {
        task(part);
    }
}

void thread_pool::worker_loop(worker& self, std::size_t slot, std::uint64_t seen) {
    running_a_part = true;
    bool just_ran = false;
    for (;;) {
        // True once a batch has started since the last one seen (or the
        // pool stops); invited says whether it asks this worker to join.
        bool invited = false;
        std::uint64_t parts = 0;
        const auto news = [&] {
            if (stopping_.load(std::memory_order_acquire)) {
                return true;
            }
            const std::uint64_t batch = batch_.load(std::memory_order_acquire);
            if (generation_of(batch) == seen) {
                return false;
            }
            seen = generation_of(batch);
            parts = parts_of(batch);
            invited = slot < parts;
            return true;
        };
        // Only a worker that took part in the last batch polls for the next:
        // one the batches have stopped using sleeps at once, and is woken
        // only by a batch that invites it.
        bool ready = false;
        if (just_ran) {
            polls_started_.fetch_add(1, std::memory_order_relaxed);
            const auto beside_caller = [this] {
                const int cpu = current_cpu();
                return cpu < 0 || cpu == caller_cpu_.load(std::memory_order_relaxed);
            };
            ready = poll_until(news, worker_poll, beside_caller);
        }
        if (!ready) {
            std::unique_lock<std::mutex> lock(state_);
            self.asleep = true;
            awake_.fetch_sub(1);
            self.wake.wait(lock, news);
            self.asleep = false;
            awake_.fetch_add(1);
        }
        if (stopping_.load(std::memory_order_acquire)) {
            awake_.fetch_sub(1);
            return;
        }
        if (!invited) {
            just_ran = false;
            continue;
        }
        if (!ready) {
            wake_ups_.fetch_add(1, std::memory_order_relaxed);
        }
        // A worker that comes after the caller has closed the batch leaves
        // it alone: its task may be gone. It still polls for the next one,
        // which a caller running back-to-back batches is about to start.
        just_ran = true;
        if (!join(seen)) {
            late_arrivals_.fetch_add(1, std::memory_order_relaxed);
            continue;
        }
        // The caller waits for every worker that joined: task_ is still this batch's.
        self.cpu.store(current_cpu(), std::memory_order_relaxed);
        take_parts(*task_.load(std::memory_order_relaxed), static_cast<std::size_t>(parts));
        left_.fetch_add(1, std::memory_order_acq_rel);
        // Taking the lock orders this notify after a caller that found a
        // joined worker unfinished has started waiting: no wake-up is lost.
        std::lock_guard<std::mutex> lock(state_);
        finished_.notify_one();
    }
}

void thread_pool::run(std::size_t parts, const std::function<void(std::size_t)>& task) {
    std::unique_lock<std::mutex> owner;
    if (parts > 1 && !running_a_part && parts <= std::numeric_limits<std::uint32_t>::max()) {
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
        caller_cpu_.store(current_cpu(), std::memory_order_relaxed);
        for (std::size_t w = 0; w + 1 < parts; ++w) {
            workers_[w]->cpu.store(-2, std::memory_order_relaxed);  // none yet: -2 matches no CPU
        }
        task_.store(&task, std::memory_order_relaxed);
        next_part_.store(1, std::memory_order_relaxed);  // part 0 is the caller's
        left_.store(0, std::memory_order_relaxed);
        const std::uint64_t generation = generation_of(batch_.load(std::memory_order_relaxed)) + 1;
        entry_.store(generation << 32, std::memory_order_relaxed);
        batch_.store((generation << 32) | parts, std::memory_order_release);
        // Only the workers invited are woken; a polling one sees the batch itself.
        for (std::size_t w = 0; w + 1 < parts; ++w) {
            if (workers_[w]->asleep) {
                workers_[w]->wake.notify_one();
            }
        }
    }
    running_a_part = true;
    task(0);
    take_parts(task, parts);
    running_a_part = false;
    // Every part is taken: no worker joins from here on, and only those that
    // joined are waited for.
    const std::uint64_t joined = entry_.fetch_or(closed_bit, std::memory_order_acq_rel) & joined_mask;
    auto all_done = [&] { return left_.load(std::memory_order_acquire) == joined; };
    // A joined worker on the caller's CPU runs only when the caller lets it.
    const auto worker_beside = [&] {
        const int cpu = current_cpu();
        for (std::size_t w = 0; w + 1 < parts; ++w) {
            if (cpu < 0 || workers_[w]->cpu.load(std::memory_order_relaxed) == cpu) {
                return true;
            }
        }
        return false;
    };
    if (!poll_until(all_done, caller_poll, worker_beside)) {
        std::unique_lock<std::mutex> lock(state_);
        finished_.wait(lock, all_done);
    }
}

}  // namespace obbsat::detail
