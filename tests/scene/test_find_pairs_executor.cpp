// The caller's executor (collide_options::executor, obbsat/executor.hpp)
// running the scene queries and the pair-list batch: the same pairs and
// verdicts as the library's own pool and as one thread, whichever way the
// executor runs the ranges (in reverse order, one std::thread per range, all
// in one range on the calling thread); find_pairs_each hands every pair
// once; an error inside a unit (a sink that throws, a bad row) comes back to
// the caller as it does without an executor; and a call on an executor
// starts no thread of the library's own.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/executor.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::executor;
using obbsat::executor_task;
using obbsat::pair_index;
using obbsat::rect_pose;

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

bool pair_less(const pair_index& x, const pair_index& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

// The executors. Each counts the ranges it was handed, so that a test sees it ran.

/// Every item a range of its own, run in reverse order before enqueue returns.
void* enqueue_reversed(executor_task task, std::size_t count, std::size_t, void* task_context, void* user) {
    for (std::size_t i = count; i-- > 0;) {
        task(i, i + 1, task_context);
        static_cast<std::atomic<std::size_t>*>(user)->fetch_add(1);
    }
    return nullptr;
}

/// Everything in one range on the calling thread.
void* enqueue_inline(executor_task task, std::size_t count, std::size_t, void* task_context, void* user) {
    task(0, count, task_context);
    static_cast<std::atomic<std::size_t>*>(user)->fetch_add(1);
    return nullptr;
}

/// One std::thread per range of `min_range` items; finish joins them.
struct threads_per_range {
    std::vector<std::thread> running;
    std::atomic<std::size_t> ranges{0};
};
void* enqueue_threads(executor_task task, std::size_t count, std::size_t min_range, void* task_context, void* user) {
    auto& self = *static_cast<threads_per_range*>(user);
    const std::size_t step = std::max<std::size_t>(1, min_range);
    for (std::size_t begin = 0; begin < count; begin += step) {
        const std::size_t end = std::min(count, begin + step);
        self.running.emplace_back([=] { task(begin, end, task_context); });
        self.ranges.fetch_add(1);
    }
    return &self;
}
void finish_threads(void* handle, void*) {
    auto& self = *static_cast<threads_per_range*>(handle);
    for (std::thread& t : self.running) {
        t.join();
    }
    self.running.clear();
}
void finish_nothing(void*, void*) {}

/// The three executors, and the ranges each has run.
struct test_executors {
    std::atomic<std::size_t> reversed_ranges{0};
    std::atomic<std::size_t> inline_ranges{0};
    threads_per_range threaded;
    executor reversed{&enqueue_reversed, &finish_nothing, &reversed_ranges};
    executor in_line{&enqueue_inline, &finish_nothing, &inline_ranges};
    executor per_thread{&enqueue_threads, &finish_threads, &threaded};

    std::vector<std::pair<const char*, const executor*>> all() const {
        return {{"reversed", &reversed}, {"inline", &in_line}, {"thread per range", &per_thread}};
    }
    std::size_t ranges() const { return reversed_ranges + inline_ranges + threaded.ranges; }
};

std::vector<rect_pose> scene(std::size_t boxes, obbsat::scene_sizes sizes, std::uint64_t seed, double origin = 0) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.sizes = sizes;
    spec.seed = seed;
    spec.origin_x = origin;
    return obbsat::make_pose_scene(spec);
}

collide_options on(const executor* given, unsigned threads) {
    collide_options options;
    options.test = obbsat::method::local;  // a method that runs on poses
    options.threads = threads;
    options.executor = given;
    return options;
}

/// Threads of this process (Linux), or 0 where unknown.
std::size_t process_threads() {
    std::error_code error;
    std::size_t count = 0;
    for (auto it = std::filesystem::directory_iterator("/proc/self/task", error);
         !error && it != std::filesystem::directory_iterator(); it.increment(error)) {
        ++count;
    }
    return error ? 0 : count;
}

// First in the file: when the whole file runs in one process, no earlier
// test has started the library's pool yet.
TEST(find_pairs_executor, a_query_on_an_inline_executor_starts_no_thread) {
    const std::vector<rect_pose> boxes = scene(100000, obbsat::scene_sizes::uniform, 3);
    test_executors executors;
    const std::size_t before = process_threads();
    if (before == 0) {
        GTEST_SKIP() << "no /proc/self/task to count threads";
    }
    const std::vector<pair_index> pairs = obbsat::find_pairs(boxes, on(&executors.in_line, 8));
    EXPECT_FALSE(pairs.empty());
    EXPECT_GT(executors.ranges(), 0u);
    EXPECT_EQ(process_threads(), before);
}

TEST(find_pairs_executor, find_pairs_gives_the_pairs_of_one_thread_on_every_executor) {
    test_executors executors;
    for (const auto sizes : {obbsat::scene_sizes::uniform, obbsat::scene_sizes::mixed}) {
        const std::vector<rect_pose> boxes = scene(200000, sizes, 7);
        const std::vector<pair_index> want = obbsat::find_pairs(boxes, on(nullptr, 1));
        ASSERT_FALSE(want.empty());
        EXPECT_TRUE(same_pairs(obbsat::find_pairs(boxes, on(nullptr, 4)), want)) << "pool, 4 threads";
        for (const auto& [name, given] : executors.all()) {
            for (const unsigned threads : {2u, 4u, 0u}) {
                EXPECT_TRUE(same_pairs(obbsat::find_pairs(boxes, on(given, threads)), want))
                    << name << ", " << threads << " threads, " << obbsat::scene_sizes_name(sizes);
            }
        }
    }
    EXPECT_GT(executors.reversed_ranges.load(), 0u);
    EXPECT_GT(executors.inline_ranges.load(), 0u);
    EXPECT_GT(executors.threaded.ranges.load(), 0u);
}

/// Every item a range of its own, in order; keeps the fewest items of a task.
void* enqueue_counting(executor_task task, std::size_t count, std::size_t, void* task_context, void* user) {
    auto& fewest = *static_cast<std::size_t*>(user);
    fewest = std::min(fewest, count);
    for (std::size_t i = 0; i < count; ++i) {
        task(i, i + 1, task_context);
    }
    return nullptr;
}

TEST(find_pairs_executor, a_query_on_two_threads_cuts_every_step_into_more_units_than_threads) {
    // A step cut one share a thread makes the thread with a busy core hold
    // the other back; every step of find_pairs (bounds, keys, sort, visits,
    // copy, sweep, the answer's sort) is cut into units taken as they come.
    for (const auto sizes : {obbsat::scene_sizes::uniform, obbsat::scene_sizes::mixed}) {
        const std::vector<rect_pose> boxes = scene(300000, sizes, 9);
        const std::vector<pair_index> want = obbsat::find_pairs(boxes, on(nullptr, 1));
        std::size_t fewest = std::numeric_limits<std::size_t>::max();
        const executor counting{&enqueue_counting, &finish_nothing, &fewest};
        EXPECT_TRUE(same_pairs(obbsat::find_pairs(boxes, on(&counting, 2)), want)) << obbsat::scene_sizes_name(sizes);
        ASSERT_NE(fewest, std::numeric_limits<std::size_t>::max()) << "no step ran on the executor";
        EXPECT_GT(fewest, 2u) << "a step of " << obbsat::scene_sizes_name(sizes) << " cut into as many units as threads";
    }
}

TEST(find_pairs_executor, a_query_across_two_sets_gives_the_same_pairs_on_every_executor) {
    const std::vector<rect_pose> a = scene(120000, obbsat::scene_sizes::mixed, 11);
    const std::vector<rect_pose> b = scene(90000, obbsat::scene_sizes::mixed, 12, 5.0);
    const std::vector<pair_index> want = obbsat::find_pairs(a, b, on(nullptr, 1));
    ASSERT_FALSE(want.empty());
    test_executors executors;
    for (const auto& [name, given] : executors.all()) {
        EXPECT_TRUE(same_pairs(obbsat::find_pairs(a, b, on(given, 4)), want)) << name;
    }
}

TEST(find_pairs_executor, find_pairs_each_hands_every_pair_once_on_every_executor) {
    const std::vector<rect_pose> boxes = scene(200000, obbsat::scene_sizes::uniform, 5);
    const std::vector<pair_index> want = obbsat::find_pairs(boxes, on(nullptr, 1));
    test_executors executors;
    for (const auto& [name, given] : executors.all()) {
        std::vector<pair_index> got;
        obbsat::find_pairs_each(boxes, on(given, 4), [&](const pair_index* pairs, std::size_t count) {
            got.insert(got.end(), pairs, pairs + count);  // the sink is called one chunk at a time
        });
        std::sort(got.begin(), got.end(), pair_less);
        EXPECT_TRUE(same_pairs(got, want)) << name << ": " << got.size() << " pairs handed, " << want.size()
                                           << " wanted (a pair handed twice shows as more)";
    }
}

TEST(find_pairs_executor, pair_finder_over_moving_frames_gives_the_pairs_of_a_fresh_query_on_every_executor) {
    std::vector<rect_pose> boxes = scene(150000, obbsat::scene_sizes::uniform, 9);
    test_executors executors;
    std::vector<obbsat::pair_finder> finders;
    for (const auto& named : executors.all()) {
        finders.emplace_back(on(named.second, 4));
    }
    obbsat::pair_finder pool_finder(on(nullptr, 4));
    for (int frame = 0; frame < 6; ++frame) {
        const std::vector<pair_index> want = obbsat::find_pairs(boxes, on(nullptr, 1));
        EXPECT_TRUE(same_pairs(pool_finder.find(boxes), want)) << "pool, frame " << frame;
        for (std::size_t f = 0; f < finders.size(); ++f) {
            EXPECT_TRUE(same_pairs(finders[f].find(boxes), want)) << executors.all()[f].first << ", frame " << frame;
        }
        // Small motion (the kept candidates answer) and, every third frame, a jump (a full query).
        const float step = frame % 3 == 2 ? 0.5f : 0.002f;
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            boxes[i].center.x += step * static_cast<float>(static_cast<int>(i % 7) - 3);
        }
    }
}

TEST(find_pairs_executor, pair_finder_with_ids_over_erased_and_appended_rows_on_every_executor) {
    // Rows erased and appended each frame: the answer is read in shares, on the executor.
    std::vector<rect_pose> pool = scene(90000, obbsat::scene_sizes::uniform, 10);
    std::vector<rect_pose> boxes(pool.begin(), pool.begin() + 60000);
    std::vector<std::uint64_t> ids(boxes.size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        ids[i] = i;
    }
    std::size_t next = boxes.size();
    test_executors executors;
    std::vector<obbsat::pair_finder> finders;
    for (const auto& named : executors.all()) {
        finders.emplace_back(on(named.second, 2));
    }
    std::size_t reused = 0;
    for (int frame = 0; frame < 6; ++frame) {
        if (frame > 1) {
            for (std::size_t c = 0; c < 300; ++c) {
                const std::size_t at = (c * 7919 + static_cast<std::size_t>(frame) * 104729) % boxes.size();
                boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(at));
                ids.erase(ids.begin() + static_cast<std::ptrdiff_t>(at));
            }
            for (std::size_t c = 0; c < 300; ++c) {
                boxes.push_back(pool[next % pool.size()]);
                ids.push_back(next++);
            }
            for (std::size_t i = 0; i < boxes.size(); ++i) {
                boxes[i].center.x += 0.002f * static_cast<float>(static_cast<int>(i % 7) - 3);
            }
        }
        const obbsat::box_view view(boxes);
        const std::vector<pair_index> want = obbsat::find_pairs(view, on(nullptr, 1));
        for (std::size_t f = 0; f < finders.size(); ++f) {
            EXPECT_TRUE(same_pairs(finders[f].find(view.with_ids(ids)), want))
                << executors.all()[f].first << ", frame " << frame;
            reused += frame > 1 && finders[f].stats().reused_candidates ? 1u : 0u;
        }
    }
    EXPECT_GE(reused, 3 * finders.size()) << "frames answered from kept candidates";
    EXPECT_GT(executors.ranges(), 0u);
}

TEST(find_pairs_executor, collide_pairs_gives_the_verdicts_of_one_thread_on_every_executor) {
    const std::vector<rect_pose> boxes = scene(50000, obbsat::scene_sizes::mixed, 13);
    const obbsat::pose_records poses(boxes);
    std::vector<pair_index> pairs;
    for (std::uint32_t i = 0; i + 1 < boxes.size(); ++i) {
        pairs.push_back({i, i + 1});
        pairs.push_back({i, (i * 7919u) % static_cast<std::uint32_t>(boxes.size())});
    }
    const std::vector<std::uint8_t> want = obbsat::collide_pairs(poses, pairs, on(nullptr, 1));
    ASSERT_NE(std::count(want.begin(), want.end(), 1), 0);
    test_executors executors;
    for (const auto& [name, given] : executors.all()) {
        EXPECT_EQ(obbsat::collide_pairs(poses, pairs, on(given, 4)), want) << name;
    }
    EXPECT_GT(executors.ranges(), 0u);
}

TEST(find_pairs_executor, a_sink_that_throws_on_an_executor_throws_to_the_caller) {
    const std::vector<rect_pose> boxes = scene(200000, obbsat::scene_sizes::uniform, 5);
    test_executors executors;
    for (const auto& [name, given] : executors.all()) {
        EXPECT_THROW(obbsat::find_pairs_each(boxes, on(given, 4),
                                             [](const pair_index*, std::size_t) {
                                                 throw std::runtime_error("the caller's sink");
                                             }),
                     std::runtime_error)
            << name;
    }
    EXPECT_TRUE(executors.threaded.running.empty());
}

TEST(find_pairs_executor, a_bad_row_is_named_as_without_an_executor) {
    std::vector<rect_pose> boxes = scene(200000, obbsat::scene_sizes::uniform, 5);
    boxes[150001].center.y = std::numeric_limits<float>::quiet_NaN();
    boxes[170002].half_extents.x = std::numeric_limits<float>::infinity();
    std::string want;
    try {
        obbsat::find_pairs(boxes, on(nullptr, 1));
        FAIL() << "no error without an executor";
    } catch (const obbsat::invalid_input& e) {
        want = e.what();
    }
    test_executors executors;
    for (const auto& [name, given] : executors.all()) {
        try {
            obbsat::find_pairs(boxes, on(given, 4));
            ADD_FAILURE() << name << ": no error";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_EQ(std::string(e.what()), want) << name;
        }
    }
}

TEST(find_pairs_executor, an_executor_without_finish_is_refused) {
    const std::vector<rect_pose> boxes = scene(100000, obbsat::scene_sizes::uniform, 3);
    std::atomic<std::size_t> ranges{0};
    const executor half{&enqueue_inline, nullptr, &ranges};
    EXPECT_THROW(obbsat::find_pairs(boxes, on(&half, 4)), obbsat::invalid_input);
}

}  // namespace
