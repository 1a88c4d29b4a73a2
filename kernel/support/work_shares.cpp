// Running work units (work_shares.hpp) on the thread pool or the caller's executor.
#include "support/work_shares.hpp"

#include "support/executor_scope.hpp"
#include "support/thread_pool.hpp"

#include <obbsat/error.hpp>

#include <atomic>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

namespace obbsat::detail {

namespace {

// True on a thread while it runs units an executor handed it: work started
// there runs on that thread alone (the executor's own threads are busy with
// the units, and the pool must not be started on the executor's behalf).
thread_local bool running_executor_units = false;

/// One run of units: the task, and the first failure by unit.
class unit_run {
public:
    unit_run(std::size_t units, const std::function<void(std::size_t)>& task) : units_(units), task_(task) {}

    /// Runs unit `unit` unless a unit has failed; keeps its exception.
    void run(std::size_t unit) {
        if (failed_.load(std::memory_order_relaxed)) {
            return;
        }
        try {
            task_(unit);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(failure_mutex_);
            if (unit < failed_unit_) {
                failed_unit_ = unit;
                failure_ = std::current_exception();
            }
            failed_.store(true, std::memory_order_relaxed);
        }
    }

    /// Throws the kept exception, if any.
    void rethrow() const {
        if (failure_) {
            std::rethrow_exception(failure_);
        }
    }

    std::size_t units() const { return units_; }

private:
    std::size_t units_;
    const std::function<void(std::size_t)>& task_;
    std::atomic<bool> failed_{false};
    std::mutex failure_mutex_;
    std::size_t failed_unit_ = std::numeric_limits<std::size_t>::max();
    std::exception_ptr failure_;
};

/// A run of units handed to an executor: each unit marked as it is taken,
/// so that one run twice or outside the task is refused, not run.
struct executor_run {
    unit_run& units;
    std::unique_ptr<std::atomic<unsigned char>[]> taken;
    std::atomic<bool> misused{false};
};

// The task an executor runs; it never throws (unit_run::run keeps what a unit throws).
void run_executor_range(std::size_t begin, std::size_t end, void* context) noexcept {
    executor_run& run = *static_cast<executor_run*>(context);
    if (begin > end || end > run.units.units()) {
        run.misused.store(true);
        return;
    }
    const bool outer = running_executor_units;
    running_executor_units = true;
    for (std::size_t unit = begin; unit < end; ++unit) {
        if (run.taken[unit].exchange(1) != 0) {
            run.misused.store(true);
            continue;
        }
        run.units.run(unit);
    }
    running_executor_units = outer;
}

void run_on_executor(const executor& given, unit_run& units) {
    if (given.enqueue == nullptr || given.finish == nullptr) {
        throw invalid_input("collide_options::executor needs both enqueue and finish");
    }
    executor_run run{units, std::make_unique<std::atomic<unsigned char>[]>(units.units()), {}};
    for (std::size_t unit = 0; unit < units.units(); ++unit) {
        run.taken[unit].store(0, std::memory_order_relaxed);
    }
    void* const handle = given.enqueue(&run_executor_range, units.units(), 1, &run, given.user_context);
    if (handle != nullptr) {
        given.finish(handle, given.user_context);
    }
    bool all_taken = true;
    for (std::size_t unit = 0; unit < units.units(); ++unit) {
        all_taken &= run.taken[unit].load() != 0;
    }
    if (run.misused.load() || !all_taken) {
        throw invalid_input("collide_options::executor did not run each of the " + std::to_string(units.units()) +
                            " items [0, " + std::to_string(units.units()) +
                            ") of its task exactly once before finish returned");
    }
}

}  // namespace

void run_unit_list(std::size_t units, std::size_t threads, const std::function<void(std::size_t)>& task) {
    unit_run run(units, task);
    const executor* const given = executor_scope::current();
    // On a thread running an executor's units, executor_scope::current() is
    // that thread's own (usually none), so the flag is asked first: work
    // started inside a unit stays on its thread, never on the pool.
    if (!running_executor_units && given != nullptr) {
        run_on_executor(*given, run);
    } else if (running_executor_units || threads <= 1) {
        for (std::size_t unit = 0; unit < units; ++unit) {
            run.run(unit);
        }
    } else {
        std::atomic<std::size_t> next{0};
        thread_pool::shared().run(std::min(threads, units), [&](std::size_t) {
            for (std::size_t unit = next.fetch_add(1, std::memory_order_relaxed); unit < units;
                 unit = next.fetch_add(1, std::memory_order_relaxed)) {
                run.run(unit);
            }
        });
    }
    run.rethrow();
}

}  // namespace obbsat::detail
