// The persistent pool (support/thread_pool.hpp): run(parts, task) runs every
// part exactly once and returns only when all have finished, for no part, one
// and many, from one run to the next as the number of parts grows and
// shrinks, after the workers have gone to sleep, and when a part is slow. The
// calling thread runs part 0; a run started while another holds the pool (a
// part that runs a batch of its own, or a second thread) runs its parts one
// after another on the calling thread. The header asks that a task not throw:
// nothing is promised for one that does, so nothing is tested. Workers a run
// does not use are neither woken nor left polling by it, and a worker that
// ran a part goes to sleep soon after (the pool's counters of wake-ups and
// polls, and of workers awake). A run never waits for a worker that has not
// joined it: the caller takes the parts left, and a worker that comes once
// all are taken runs nothing (the pool's counter of late arrivals).
#include "support/thread_pool.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace {

using obbsat::detail::thread_pool;

/// Runs `parts` parts that each count their own runs in plain ints (so that
/// a run returning before a part's write is seen shows up as a wrong count)
/// and returns the counts.
std::vector<int> run_counts(std::size_t parts) {
    std::vector<int> runs(parts + 1, 0);  // one past the last part: never written
    thread_pool::shared().run(parts, [&](std::size_t part) { runs.at(part) += 1; });
    return runs;
}

void expect_each_part_once(std::size_t parts, const std::string& what) {
    const std::vector<int> runs = run_counts(parts);
    for (std::size_t p = 0; p < parts; ++p) {
        ASSERT_EQ(runs[p], 1) << what << ": part " << p << " of " << parts;
    }
    EXPECT_EQ(runs[parts], 0) << what << ": a part past the last ran";
}

TEST(thread_pool, no_part_runs_nothing) {
    bool called = false;
    thread_pool::shared().run(0, [&](std::size_t) { called = true; });
    EXPECT_FALSE(called);
}

TEST(thread_pool, every_part_runs_exactly_once_for_one_to_eight_parts) {
    for (const std::size_t parts : {1u, 2u, 3u, 4u, 5u, 8u}) {
        expect_each_part_once(parts, "first runs");
    }
}

TEST(thread_pool, back_to_back_runs_that_grow_and_shrink_run_every_part_once) {
    // Workers with no part in a run must sit it out and still take their part
    // in the next one; a worker must never run a part of an earlier run again.
    const std::size_t sizes[] = {4, 1, 2, 4, 3, 1, 0, 4, 2, 2, 5, 1, 3};
    for (int round = 0; round < 30; ++round) {
        for (const std::size_t parts : sizes) {
            expect_each_part_once(parts, "round " + std::to_string(round));
            if (HasFatalFailure()) {
                return;
            }
        }
    }
}

TEST(thread_pool, runs_after_the_workers_went_to_sleep_run_every_part_once) {
    // The workers spin for well under a millisecond before they sleep.
    for (int round = 0; round < 5; ++round) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        expect_each_part_once(4, "after a pause, round " + std::to_string(round));
    }
}

TEST(thread_pool, returns_only_when_the_slowest_part_has_finished) {
    // A part slower than the caller's spin makes it wait on the condition.
    for (const std::size_t slow : {0u, 1u, 3u}) {
        std::vector<int> finished(4, 0);
        thread_pool::shared().run(4, [&](std::size_t part) {
            if (part == slow) {
                std::this_thread::sleep_for(std::chrono::milliseconds(30));
            }
            finished[part] = 1;
        });
        EXPECT_EQ(finished, (std::vector<int>{1, 1, 1, 1})) << "slow part " << slow;
    }
}

TEST(thread_pool, the_calling_thread_runs_part_zero) {
    const std::thread::id caller = std::this_thread::get_id();
    for (const std::size_t parts : {1u, 2u, 4u}) {
        std::vector<std::thread::id> ran_on(parts);
        thread_pool::shared().run(parts, [&](std::size_t part) { ran_on[part] = std::this_thread::get_id(); });
        EXPECT_EQ(ran_on[0], caller) << parts << " parts";
    }
}

TEST(thread_pool, parts_of_a_run_run_at_the_same_time_on_other_threads) {
    // Four parts each wait (for at most ten seconds) until all four have
    // started: only a pool that runs them side by side lets them all through.
    constexpr std::size_t parts = 4;
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<std::size_t> started{0};
    std::vector<int> met(parts, 0);
    std::vector<std::thread::id> ran_on(parts);
    thread_pool::shared().run(parts, [&](std::size_t part) {
        ran_on[part] = std::this_thread::get_id();
        started.fetch_add(1);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (started.load() < parts && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::yield();
        }
        met[part] = started.load() == parts ? 1 : 0;
    });
    EXPECT_EQ(met, (std::vector<int>{1, 1, 1, 1}));
    const std::set<std::thread::id> threads(ran_on.begin(), ran_on.end());
    EXPECT_EQ(threads.size(), parts);
    EXPECT_EQ(ran_on[0], caller);
}

TEST(thread_pool, a_run_inside_a_part_runs_its_parts_in_order_on_that_parts_thread) {
    // The outer run holds the pool, so every inner run is one after another
    // on the thread of the outer part that started it.
    constexpr std::size_t outer = 3;
    constexpr std::size_t inner = 5;
    std::vector<std::vector<std::size_t>> order(outer);
    std::vector<int> same_thread(outer, 0);
    thread_pool::shared().run(outer, [&](std::size_t o) {
        const std::thread::id here = std::this_thread::get_id();
        bool same = true;
        thread_pool::shared().run(inner, [&](std::size_t i) {
            order[o].push_back(i);
            same = same && std::this_thread::get_id() == here;
        });
        same_thread[o] = same ? 1 : 0;
    });
    for (std::size_t o = 0; o < outer; ++o) {
        EXPECT_EQ(order[o], (std::vector<std::size_t>{0, 1, 2, 3, 4})) << "outer part " << o;
        EXPECT_EQ(same_thread[o], 1) << "outer part " << o;
    }
    // The pool is free again afterwards.
    expect_each_part_once(4, "after the nested runs");
}

TEST(thread_pool, runs_from_several_threads_at_once_each_run_every_part_once) {
    // Whichever thread does not get the pool runs its parts itself.
    constexpr std::size_t threads = 3;
    constexpr std::size_t rounds = 200;
    std::vector<int> wrong(threads, 0);
    std::vector<std::thread> callers;
    for (std::size_t t = 0; t < threads; ++t) {
        callers.emplace_back([&, t] {
            for (std::size_t round = 0; round < rounds; ++round) {
                const std::size_t parts = 1 + (round + t) % 4;
                std::vector<int> runs(parts, 0);
                thread_pool::shared().run(parts, [&](std::size_t part) { runs[part] += 1; });
                wrong[t] += static_cast<int>(std::count_if(runs.begin(), runs.end(), [](int r) { return r != 1; }));
            }
        });
    }
    for (auto& c : callers) {
        c.join();
    }
    EXPECT_EQ(wrong, std::vector<int>(threads, 0));
}

TEST(thread_pool, shared_is_one_pool) {
    EXPECT_EQ(&thread_pool::shared(), &thread_pool::shared());
    thread_pool* from_other_thread = nullptr;
    std::thread([&] { from_other_thread = &thread_pool::shared(); }).join();
    EXPECT_EQ(from_other_thread, &thread_pool::shared());
}

TEST(thread_pool, many_more_parts_than_cores_run_every_part_once) {
    for (const std::size_t parts : {16u, 64u, 3u, 64u}) {
        expect_each_part_once(parts, "many parts");
    }
}

/// Waits (at most ten seconds) until every worker of the pool sleeps; true if they all do.
bool all_workers_asleep_within_ten_seconds() {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (thread_pool::shared().awake_workers() != 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

TEST(thread_pool, after_a_run_on_many_threads_a_run_on_two_wakes_and_polls_with_one_worker_only) {
    // The pool keeps every worker it ever started; those the later, smaller
    // runs do not use must neither be woken by them nor poll for them, or a
    // process that once ran on 64 threads keeps 63 of them busy on 2 cores.
    thread_pool& pool = thread_pool::shared();
    expect_each_part_once(64, "the wide run");
    ASSERT_GE(pool.workers(), 63u);
    ASSERT_TRUE(all_workers_asleep_within_ten_seconds()) << pool.awake_workers() << " workers still awake";
    const std::uint64_t polls = pool.polls_started();
    const std::uint64_t wakes = pool.wake_ups();
    for (int round = 0; round < 10; ++round) {
        expect_each_part_once(2, "a narrow run after the wide one");
    }
    // Idle workers sleep soon: polling is bounded.
    ASSERT_TRUE(all_workers_asleep_within_ten_seconds()) << pool.awake_workers() << " workers still awake";
    // Ten runs of two parts: worker 0 (part 1) at most wakes or polls once per run.
    EXPECT_LE(pool.wake_ups() - wakes, 10u);
    EXPECT_LE(pool.polls_started() - polls, 10u);
}

TEST(thread_pool, a_run_takes_the_parts_of_a_worker_not_there_yet_which_then_runs_nothing) {
    // With the workers asleep, a run of two parts that take no time is over
    // before the woken worker gets to it (waking takes microseconds): the
    // caller runs part 1 itself, returns without waiting for the worker, and
    // the worker, coming to a batch already closed, runs nothing of it.
    thread_pool& pool = thread_pool::shared();
    const std::thread::id caller = std::this_thread::get_id();
    const std::uint64_t late_before = pool.late_arrivals();
    bool caller_ran_both = false;
    for (int round = 0; round < 50 && !caller_ran_both; ++round) {
        ASSERT_TRUE(all_workers_asleep_within_ten_seconds()) << pool.awake_workers() << " workers still awake";
        std::vector<std::thread::id> ran_on(2);
        std::vector<int> runs(2, 0);
        pool.run(2, [&](std::size_t part) {
            ran_on[part] = std::this_thread::get_id();
            runs[part] += 1;
        });
        ASSERT_EQ(runs, (std::vector<int>{1, 1})) << "round " << round;
        caller_ran_both = ran_on[1] == caller;
    }
    EXPECT_TRUE(caller_ran_both) << "part 1 always waited for a worker";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (pool.late_arrivals() == late_before && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_GT(pool.late_arrivals(), late_before) << "no worker came to a batch after it was closed";
}

TEST(thread_pool, a_worker_that_ran_a_part_sleeps_soon_after) {
    thread_pool& pool = thread_pool::shared();
    expect_each_part_once(4, "a run");
    ASSERT_TRUE(all_workers_asleep_within_ten_seconds()) << pool.awake_workers() << " workers still awake";
    EXPECT_EQ(pool.awake_workers(), 0u);
}

}  // namespace
