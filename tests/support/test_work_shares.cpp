// Work units (support/work_shares.hpp): run_units runs every unit exactly
// once, over the thread pool or over the executor in scope
// (support/executor_scope.hpp); an exception from a unit comes back to the
// caller; an executor that leaves a unit out, runs one twice or names items
// past the task's is refused with invalid_input; units_for cuts as it says.
#include "support/executor_scope.hpp"
#include "support/work_shares.hpp"

#include <obbsat/error.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

using obbsat::executor;
using obbsat::executor_task;
using obbsat::detail::executor_scope;
using obbsat::detail::run_units;
using obbsat::detail::units_for;

/// Runs `units` units on `threads` threads; each counts its runs in a plain int.
std::vector<int> unit_counts(std::size_t units, std::size_t threads) {
    std::vector<int> runs(units, 0);
    run_units(units, threads, [&](std::size_t unit) { runs.at(unit) += 1; });
    return runs;
}

TEST(work_units, units_for_cuts_a_few_units_a_thread_none_below_the_smallest) {
    EXPECT_EQ(units_for(1000000, 1, 100), 1u);
    EXPECT_EQ(units_for(1000000, 2, 100), 2 * obbsat::detail::units_per_thread);
    EXPECT_EQ(units_for(1000, 2, 100), 10u);
    EXPECT_EQ(units_for(100, 4, 100), 4u);  // never fewer units than threads
}

TEST(work_units, every_unit_runs_exactly_once_on_the_pool) {
    for (const std::size_t threads : {1u, 2u, 3u, 8u}) {
        for (const std::size_t units : {0u, 1u, 2u, 7u, 64u, 1000u}) {
            EXPECT_EQ(unit_counts(units, threads), std::vector<int>(units, 1))
                << units << " units on " << threads << " threads";
        }
    }
}

TEST(work_units, a_unit_that_throws_is_thrown_again_on_the_caller_the_lowest_first) {
    for (const std::size_t threads : {1u, 2u, 4u}) {
        try {
            run_units(32, threads, [](std::size_t unit) {
                if (unit == 5 || unit == 6) {
                    throw std::runtime_error("unit " + std::to_string(unit));
                }
            });
            ADD_FAILURE() << "nothing thrown on " << threads << " threads";
        } catch (const std::runtime_error& e) {
            // Unit 6 may be skipped or run, but unit 5 always runs before 6 fails on one thread.
            if (threads == 1) {
                EXPECT_STREQ(e.what(), "unit 5");
            }
        }
    }
}

// Executors for the tests: each keeps what it needs in its user context.

/// Runs every item, one range each, in reverse order, before enqueue returns.
void* enqueue_reversed(executor_task task, std::size_t count, std::size_t, void* task_context, void*) {
    for (std::size_t i = count; i-- > 0;) {
        task(i, i + 1, task_context);
    }
    return nullptr;
}

/// Runs everything in one range on the calling thread.
void* enqueue_inline(executor_task task, std::size_t count, std::size_t, void* task_context, void*) {
    task(0, count, task_context);
    return nullptr;
}

/// One std::thread per range of three items; finish joins them.
struct thread_per_range {
    std::vector<std::thread> running;
    std::mutex ids_mutex;
};
void* enqueue_threads(executor_task task, std::size_t count, std::size_t, void* task_context, void* user) {
    auto& self = *static_cast<thread_per_range*>(user);
    for (std::size_t begin = 0; begin < count; begin += 3) {
        const std::size_t end = std::min(count, begin + 3);
        self.running.emplace_back([=] { task(begin, end, task_context); });
    }
    return &self;
}
void finish_threads(void* handle, void*) {
    auto& self = *static_cast<thread_per_range*>(handle);
    for (auto& t : self.running) {
        t.join();
    }
    self.running.clear();
}
void finish_nothing(void*, void*) {}

TEST(work_units, with_an_executor_every_unit_runs_once_on_its_threads_and_none_on_the_pool) {
    thread_per_range state;
    const executor reversed{&enqueue_reversed, &finish_nothing, nullptr};
    const executor in_line{&enqueue_inline, &finish_nothing, nullptr};
    const executor threaded{&enqueue_threads, &finish_threads, &state};
    const std::thread::id caller = std::this_thread::get_id();
    for (const executor* given : {&reversed, &in_line, &threaded}) {
        const executor_scope scope(given);
        std::vector<int> runs(40, 0);
        std::vector<std::thread::id> ran_on(40);
        run_units(40, 4, [&](std::size_t unit) {
            runs[unit] += 1;
            ran_on[unit] = std::this_thread::get_id();
            // Work started inside a unit runs on that unit's thread.
            run_units(3, 4, [&](std::size_t) { EXPECT_EQ(std::this_thread::get_id(), ran_on[unit]); });
        });
        EXPECT_EQ(runs, std::vector<int>(40, 1));
        for (const std::thread::id id : ran_on) {
            if (given == &threaded) {
                EXPECT_NE(id, caller);
            } else {
                EXPECT_EQ(id, caller);
            }
        }
    }
    EXPECT_EQ(executor_scope::current(), nullptr);  // the scopes put the pool back
}

TEST(work_units, an_error_in_a_unit_on_an_executor_comes_back_after_finish) {
    thread_per_range state;
    const executor threaded{&enqueue_threads, &finish_threads, &state};
    const executor_scope scope(&threaded);
    EXPECT_THROW(run_units(10, 2,
                           [](std::size_t unit) {
                               if (unit == 4) {
                                   throw std::runtime_error("unit 4");
                               }
                           }),
                 std::runtime_error);
    EXPECT_TRUE(state.running.empty());  // finish ran before the throw
}

void* enqueue_skipping_last(executor_task task, std::size_t count, std::size_t, void* task_context, void*) {
    task(0, count - 1, task_context);
    return nullptr;
}
void* enqueue_twice(executor_task task, std::size_t count, std::size_t, void* task_context, void*) {
    task(0, count, task_context);
    task(0, 1, task_context);
    return nullptr;
}
void* enqueue_past_the_end(executor_task task, std::size_t count, std::size_t, void* task_context, void*) {
    task(0, count + 1, task_context);
    return nullptr;
}

TEST(work_units, an_executor_that_misses_repeats_or_overruns_items_is_refused_and_no_unit_runs_twice) {
    for (auto* enqueue : {&enqueue_skipping_last, &enqueue_twice, &enqueue_past_the_end}) {
        const executor wrong{enqueue, &finish_nothing, nullptr};
        const executor_scope scope(&wrong);
        std::vector<int> runs(8, 0);
        EXPECT_THROW(run_units(8, 2, [&](std::size_t unit) { runs.at(unit) += 1; }), obbsat::invalid_input);
        for (const int r : runs) {
            EXPECT_LE(r, 1);
        }
    }
    const executor half{&enqueue_inline, nullptr, nullptr};
    const executor_scope scope(&half);
    EXPECT_THROW(run_units(8, 2, [](std::size_t) {}), obbsat::invalid_input);
}

}  // namespace
