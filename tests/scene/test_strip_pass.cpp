// The scene query on one thread takes the copy, the visits, the merge and
// the sweep strip by strip (kernel/scene/strip_pass.cpp): the same pairs,
// visits and candidates as the steps taken one at a time over the whole
// scene (records_copy.cpp, visits.cpp, sweep.cpp), on scenes whose
// rectangles visit one strip above, many strips above, or none; across two
// sets; with pair filters; and with rows changed between the order's read
// and the copy's, which the caller must not do but which must give no crash.
// On several threads, and on a caller's executor taking the units in
// reverse, the strip pass runs over units of consecutive strips: the same
// answer, with tall boxes reaching from one unit's strips into the next
// one's; a box through every strip makes the query take the steps one at a time.
#include "scene/pair_search.hpp"
#include "support/executor_scope.hpp"
#include "test_support/pose_query_rows.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/executor.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace obbsat::detail {

struct pair_search_test_access {
    /// The steps of pair_search::run on one thread as a query on more threads takes them: the
    /// records and their sweep bounds copied for the whole scene, the visits, then the sweep.
    static void run_in_steps(pair_search& search, const query_input& input, const pair_chunk_sink& emit) {
        search.set_query(input);
        constexpr std::size_t parts = 1;
        search.used_parts_ = parts;
        search.measure_extent(input, parts, false);
        search.order_boxes(input, parts);
        search.copy_records(input, parts);
        search.collect_visits(parts);
        search.sweep(parts, &emit);
    }

    /// pair_search::run on one thread strip by strip, with `change` called
    /// after the order is made and before the first record is copied.
    static void run_strip_by_strip_with_rows_changed_after_order(pair_search& search, const query_input& input,
                                                                 const std::function<void()>& change,
                                                                 const pair_chunk_sink& emit) {
        search.set_query(input);
        search.used_parts_ = 1;
        search.measure_extent(input, 1, false);
        search.order_boxes(input, 1);
        change();
        search.copy_and_sweep(input, 1, &emit);
    }

    /// Bytes the query holds for sweep bounds of the whole scene (in_lo_x_ ... strip_hi_).
    static std::size_t scene_sweep_bytes(const pair_search& search) {
        return sizeof(float) * (search.in_lo_x_.capacity() + search.in_lo_y_.capacity() + search.in_hi_x_.capacity() +
                                search.in_hi_y_.capacity()) +
               sizeof(std::uint32_t) *
                   (search.q_lo_.capacity() + search.q_hi_.capacity() + search.strip_hi_.capacity());
    }

    static std::size_t strips(const pair_search& search) { return search.grid_.strips; }

    /// Strips of the last query's grid in one unit of y.
    static double strips_per_unit_of_y(const pair_search& search) { return search.grid_.y_scale; }

    /// Strips above its lowest a rectangle of the last query may reach, as the strip pass reckons.
    static std::size_t strip_reach(const pair_search& search) { return search.strip_reach(); }

    /// Strips of the last query's thinnest unit.
    static std::size_t thinnest_unit(const pair_search& search) {
        std::size_t thinnest = search.grid_.strips;
        for (std::size_t u = 0; u < search.used_parts_; ++u) {
            thinnest = std::min<std::size_t>(thinnest, search.parts_[u].end_strip - search.parts_[u].first_strip);
        }
        return thinnest;
    }

    /// Units of the last query's sweep.
    static std::size_t units(const pair_search& search) { return search.used_parts_; }
};

}  // namespace obbsat::detail

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat::detail::pair_search;
using obbsat::detail::pair_search_test_access;
using obbsat::detail::query_input;

/// Rows of poses in the caller's memory, checked by the query.
query_input rows_of(const std::vector<rect_pose>& a, const std::vector<rect_pose>* b = nullptr) {
    return obbsat::test_support::pose_query_rows(a, b);
}

/// `count` boxes at random in a square of side `side`, turned at random, of
/// half sizes up to 1; one in `tall_every` is up to `tall` high, so that it
/// visits many strips above its lowest.
std::vector<rect_pose> scene(std::size_t count, float side, std::size_t tall_every, float tall, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<rect_pose> out;
    for (std::size_t i = 0; i < count; ++i) {
        const float angle = random.uniform(0.0f, 6.2831853f);
        const float high = tall_every != 0 && i % tall_every == 0 ? tall : 1.0f;
        out.push_back(rect_pose{{random.uniform(0.0f, side), random.uniform(0.0f, side)},
                                {random.uniform(0.05f, 1.0f), random.uniform(0.05f, high)},
                                {std::cos(angle), std::sin(angle)}});
    }
    return out;
}

/// Pair filters for `count` boxes: four categories, one box in eight refusing
/// the second, and groups 1 to 3 on one box in sixteen.
struct pair_filter_rows {
    std::vector<std::uint64_t> categories, masks;
    std::vector<std::int32_t> groups;

    explicit pair_filter_rows(std::size_t count) : categories(count), masks(count), groups(count) {
        for (std::size_t i = 0; i < count; ++i) {
            categories[i] = std::uint64_t{1} << (i % 4);
            masks[i] = i % 8 == 0 ? ~std::uint64_t{2} : obbsat::all_categories;
            groups[i] = i % 16 == 0 ? static_cast<std::int32_t>(i % 3 + 1) : 0;
        }
    }

    /// `input` with these filters on its first set.
    query_input on(query_input input) const {
        input.a_filters.categories = categories.data();
        input.a_filters.masks = masks.data();
        input.a_filters.groups = groups.data();
        return input;
    }
};

struct answer {
    std::vector<pair_index> pairs;
    std::size_t visits = 0;
    std::size_t candidates = 0;
};

answer sorted(std::vector<pair_index> pairs, const pair_search& search) {
    std::sort(pairs.begin(), pairs.end(),
              [](const pair_index& x, const pair_index& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    return answer{pairs, search.stats().visits, search.stats().candidates};
}

/// The answer of a query on one thread, strip by strip (run) or with the steps one at a time.
answer one_thread(const query_input& input, method m, bool strip_pass) {
    collide_options options;
    options.test = m;
    options.threads = 1;
    pair_search search(options);
    std::vector<pair_index> pairs;
    const auto keep = [&](const pair_index* p, std::size_t count) { pairs.insert(pairs.end(), p, p + count); };
    if (strip_pass) {
        search.run(input, keep);
        // The query took the strip pass: no sweep bounds of the whole scene were written.
        EXPECT_EQ(pair_search_test_access::scene_sweep_bytes(search), 0u);
    } else {
        pair_search_test_access::run_in_steps(search, input, keep);
        EXPECT_GT(pair_search_test_access::scene_sweep_bytes(search), 0u);
    }
    return sorted(pairs, search);
}

answer strip_by_strip(const query_input& input, method m) { return one_thread(input, m, true); }

answer in_steps(const query_input& input, method m) { return one_thread(input, m, false); }

void expect_same(const answer& got, const answer& wanted) {
    EXPECT_EQ(got.visits, wanted.visits);
    EXPECT_EQ(got.candidates, wanted.candidates);
    ASSERT_EQ(got.pairs.size(), wanted.pairs.size());
    for (std::size_t i = 0; i < got.pairs.size(); ++i) {
        ASSERT_TRUE(got.pairs[i].a == wanted.pairs[i].a && got.pairs[i].b == wanted.pairs[i].b) << "pair " << i;
    }
}

TEST(strip_pass, answers_as_the_steps_one_at_a_time_within_one_set) {
    // Boxes of about one size (visits to the strip above only), and with one
    // in seven up to 40 high (visits many strips above, several waiting at once).
    for (const std::size_t tall_every : {std::size_t{0}, std::size_t{7}}) {
        const std::vector<rect_pose> boxes = scene(20000, 160.0f, tall_every, 40.0f, 11 + tall_every);
        const query_input input = rows_of(boxes);
        for (const method m : {method::exact, method::local, method::conservative}) {
            const answer wanted = in_steps(input, m);
            ASSERT_GT(wanted.pairs.size(), boxes.size());
            ASSERT_GT(wanted.visits, boxes.size() / 10);
            expect_same(strip_by_strip(input, m), wanted);
        }
    }
}

TEST(strip_pass, answers_as_the_steps_one_at_a_time_across_two_sets) {
    const std::vector<rect_pose> a = scene(9000, 150.0f, 5, 30.0f, 3);
    const std::vector<rect_pose> b = scene(7000, 150.0f, 0, 1.0f, 4);
    const query_input input = rows_of(a, &b);
    const answer wanted = in_steps(input, method::exact);
    ASSERT_GT(wanted.pairs.size(), 1000u);
    expect_same(strip_by_strip(input, method::exact), wanted);
}

TEST(strip_pass, answers_as_the_steps_one_at_a_time_with_pair_filters) {
    const std::vector<rect_pose> boxes = scene(12000, 180.0f, 9, 25.0f, 5);
    const pair_filter_rows filters(boxes.size());
    const query_input input = filters.on(rows_of(boxes));
    const answer wanted = in_steps(input, method::exact);
    const answer unfiltered = in_steps(rows_of(boxes), method::exact);
    ASSERT_LT(wanted.pairs.size(), unfiltered.pairs.size());
    expect_same(strip_by_strip(input, method::exact), wanted);
}

TEST(strip_pass, rows_changed_after_the_order_give_no_crash_and_no_absurd_count) {
    // A column of boxes 0.5 apart over many strips; after the order is made,
    // the top ones drop below the bottom (their highest strip below their
    // lowest) and others grow tall (visits the order's pass did not see).
    std::vector<rect_pose> poses;
    for (std::size_t i = 0; i < 2000; ++i) {
        poses.push_back(rect_pose{{0.0f, 0.5f * static_cast<float>(i)}, {0.5f, 0.5f}, {1.0f, 0.0f}});
    }
    const query_input input = rows_of(poses);
    collide_options options;
    options.test = method::exact;
    options.threads = 1;
    pair_search search(options);
    std::size_t found = 0;
    EXPECT_NO_THROW(pair_search_test_access::run_strip_by_strip_with_rows_changed_after_order(
        search, input,
        [&] {
            for (std::size_t i = poses.size() - 10; i < poses.size(); ++i) {
                poses[i].center.y = -100.0f;
            }
            for (std::size_t i = 100; i < 1000; i += 50) {
                poses[i].half_extents.y = 300.0f;
                poses[i].center.x = 0.3f;
            }
        },
        [&](const pair_index*, std::size_t count) { found += count; }));
    ASSERT_GT(pair_search_test_access::strips(search), 100u);
    EXPECT_LE(search.stats().visits, poses.size() * pair_search_test_access::strips(search));
    EXPECT_LE(found, poses.size() * (poses.size() - 1) / 2);
    // The same engine answers the rows as they are now like the steps one at a time.
    std::vector<pair_index> again;
    search.run(input, [&](const pair_index* p, std::size_t count) { again.insert(again.end(), p, p + count); });
    expect_same(sorted(again, search), in_steps(input, method::exact));
}

}  // namespace

namespace {

using obbsat::executor;
using obbsat::executor_task;

/// Every unit a range of its own, run in reverse order before enqueue returns.
void* enqueue_reversed(executor_task task, std::size_t count, std::size_t, void* task_context, void* user) {
    for (std::size_t i = count; i-- > 0;) {
        task(i, i + 1, task_context);
        static_cast<std::atomic<std::size_t>*>(user)->fetch_add(1);
    }
    return nullptr;
}

/// Nothing left to wait for: enqueue_reversed runs every unit before it returns.
void finish_nothing(void*, void*) {}

/// How a query on several threads ran: its threads, and the caller's executor or none.
struct threads_and_executor {
    unsigned threads;
    const executor* given;
};

/// The answer of a query on `run.threads` threads, run as pair_search::run
/// (strip by strip where it may); `strip_pass` tells whether it must have
/// taken the strip pass over several units, or the steps one at a time.
answer on_threads(const query_input& input, method m, threads_and_executor run, bool strip_pass) {
    collide_options options;
    options.test = m;
    options.threads = run.threads;
    options.executor = run.given;
    pair_search search(options);
    const obbsat::detail::executor_scope scope(run.given);
    std::vector<pair_index> pairs;
    search.run(input, [&](const pair_index* p, std::size_t count) { pairs.insert(pairs.end(), p, p + count); });
    if (strip_pass) {
        EXPECT_EQ(pair_search_test_access::scene_sweep_bytes(search), 0u);
        EXPECT_GT(pair_search_test_access::units(search), std::size_t{run.threads});
    } else {
        EXPECT_GT(pair_search_test_access::scene_sweep_bytes(search), 0u);
    }
    return sorted(pairs, search);
}

/// The query's answer on 2 and 3 threads and on an executor taking the
/// units in reverse, each against the steps one at a time on one thread.
void expect_same_on_threads(const query_input& input, method m, bool strip_pass) {
    const answer wanted = in_steps(input, m);
    ASSERT_GT(wanted.pairs.size(), 1000u);
    std::atomic<std::size_t> ranges{0};
    executor reversed;
    reversed.enqueue = enqueue_reversed;
    reversed.finish = finish_nothing;
    reversed.user_context = &ranges;
    for (const threads_and_executor run :
         {threads_and_executor{2, nullptr}, threads_and_executor{3, nullptr}, threads_and_executor{2, &reversed}}) {
        SCOPED_TRACE(testing::Message() << run.threads << " threads" << (run.given ? ", executor" : ""));
        expect_same(on_threads(input, m, run, strip_pass), wanted);
    }
    EXPECT_GT(ranges.load(), 2u);
}

/// A scene large enough for three threads' units, 100 wide and 2500 high so
/// that each unit holds many strips; one box in five up to `tall` high: they
/// cross from one unit's strips into the next one's.
std::vector<rect_pose> threads_scene(std::size_t count, std::size_t tall_every, float tall, std::uint64_t seed) {
    std::vector<rect_pose> boxes = scene(count, 500.0f, tall_every, tall, seed);
    for (rect_pose& box : boxes) {
        box.center.x /= 5.0f;
        box.center.y *= 5.0f;
    }
    return boxes;
}

std::vector<rect_pose> threads_scene(float tall, std::uint64_t seed) { return threads_scene(60000, 5, tall, seed); }

/// Runs a query of `input` by method exact on `threads` threads in `search`,
/// its pairs dropped: for what the query reckoned (strip_reach, units).
void run_exact(std::unique_ptr<pair_search>& search, const query_input& input, unsigned threads) {
    collide_options options;
    options.test = method::exact;
    options.threads = threads;
    search = std::make_unique<pair_search>(options);
    search->run(input, [](const pair_index*, std::size_t) {});
}

TEST(strip_pass, answers_as_the_steps_one_at_a_time_with_strips_no_box_starts_in) {
    // Three bands of boxes with wide gaps between them: strips where no box
    // has its lowest, at the bottom, between the bands and at the top of the
    // grid, on one thread and in units on several.
    std::vector<rect_pose> boxes = threads_scene(60000, 5, 6.0f, 27);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        boxes[i].center.y = boxes[i].center.y / 10.0f + 600.0f * static_cast<float>(i % 3) + 100.0f;
    }
    const query_input input = rows_of(boxes);
    const answer wanted = in_steps(input, method::exact);
    ASSERT_GT(wanted.pairs.size(), boxes.size());
    expect_same(strip_by_strip(input, method::exact), wanted);
    expect_same_on_threads(input, method::exact, true);
}

TEST(strip_pass, on_threads_answers_as_the_steps_one_at_a_time_with_units_thinner_than_the_reach) {
    // Two boxes in three in a band 40 high: there a unit holds a strip or
    // two, fewer than the tall boxes reach, so it reads the rows below its
    // first strip from the regions of several units below; some strips hold
    // more boxes than a unit, which leaves units with no strip.
    std::vector<rect_pose> boxes = threads_scene(6.0f, 29);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (i % 3 != 0) {
            boxes[i].center.y = 1250.0f + boxes[i].center.y / 2500.0f * 40.0f;
        }
    }
    std::unique_ptr<pair_search> probe;
    run_exact(probe, rows_of(boxes), 3);
    ASSERT_GE(pair_search_test_access::strip_reach(*probe), 3u);
    ASSERT_LT(pair_search_test_access::thinnest_unit(*probe), pair_search_test_access::strip_reach(*probe));
    expect_same_on_threads(rows_of(boxes), method::exact, true);
}

TEST(strip_pass, reads_below_a_unit_as_many_strips_as_the_tallest_box_reaches) {
    // Boxes 2 high over strips taller than that reach at most the strip
    // above their lowest; one box 14 high, a few strips, at most
    // floor(its height in strips) + 1 above. A unit reads that many strips
    // below its first, no more.
    std::vector<rect_pose> boxes;
    obbsat::seeded_random random(26);
    for (std::size_t i = 0; i < 20000; ++i) {
        boxes.push_back(rect_pose{{random.uniform(0.0f, 500.0f), random.uniform(0.0f, 500.0f)},
                                  {random.uniform(0.05f, 1.0f), 1.0f},
                                  {1.0f, 0.0f}});
    }
    std::unique_ptr<pair_search> search;
    run_exact(search, rows_of(boxes), 2);
    EXPECT_EQ(pair_search_test_access::strip_reach(*search), 1u);
    boxes[7].half_extents.y = 7.0f;
    run_exact(search, rows_of(boxes), 2);
    const double tall_in_strips = 14.0 * pair_search_test_access::strips_per_unit_of_y(*search);
    ASSERT_GT(tall_in_strips, 2.0);
    ASSERT_GT(std::abs(tall_in_strips - std::round(tall_in_strips)), 0.1);  // no rounding at stake
    EXPECT_EQ(pair_search_test_access::strip_reach(*search), static_cast<std::size_t>(tall_in_strips) + 1);
}

TEST(strip_pass, on_threads_answers_as_the_steps_one_at_a_time_within_one_set) {
    const std::vector<rect_pose> boxes = threads_scene(6.0f, 21);
    const query_input input = rows_of(boxes);
    std::unique_ptr<pair_search> probe;
    run_exact(probe, input, 2);
    // Tall boxes reach several strips above their lowest, past the first strip of the next unit.
    ASSERT_GE(pair_search_test_access::strip_reach(*probe), 3u);
    for (const method m : {method::exact, method::local, method::conservative}) {
        expect_same_on_threads(input, m, true);
    }
}

TEST(strip_pass, on_threads_answers_as_the_steps_one_at_a_time_across_two_sets) {
    const std::vector<rect_pose> a = threads_scene(6.0f, 22);
    const std::vector<rect_pose> b = threads_scene(30000, 3, 5.0f, 23);
    expect_same_on_threads(rows_of(a, &b), method::exact, true);
}

TEST(strip_pass, on_threads_answers_as_the_steps_one_at_a_time_with_pair_filters) {
    const std::vector<rect_pose> boxes = threads_scene(6.0f, 24);
    const pair_filter_rows filters(boxes.size());
    const query_input input = filters.on(rows_of(boxes));
    ASSERT_LT(in_steps(input, method::exact).pairs.size(), in_steps(rows_of(boxes), method::exact).pairs.size());
    expect_same_on_threads(input, method::exact, true);
}

TEST(strip_pass, on_threads_with_a_box_through_every_strip_answers_as_the_steps_one_at_a_time) {
    // One box as tall as the scene visits every strip: each unit would read
    // every row below it again, so the query takes the steps one at a time.
    std::vector<rect_pose> boxes = threads_scene(6.0f, 25);
    boxes[boxes.size() / 2] = rect_pose{{50.0f, 1250.0f}, {3.0f, 1300.0f}, {1.0f, 0.0f}};
    expect_same_on_threads(rows_of(boxes), method::exact, false);
}

}  // namespace
