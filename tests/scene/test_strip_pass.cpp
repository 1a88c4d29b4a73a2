// The scene query on one thread takes the copy, the visits, the merge and
// the sweep strip by strip (kernel/scene/strip_pass.cpp): the same pairs,
// visits and candidates as the steps taken one at a time over the whole
// scene (records_copy.cpp, visits.cpp, sweep.cpp), on scenes whose
// rectangles visit one strip above, many strips above, or none; across two
// sets; with pair filters; and with rows changed between the order's read
// and the copy's, which the caller must not do but which must give no crash.
#include "scene/pair_search.hpp"
#include "test_support/pose_query_rows.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
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
        search.copy_and_sweep(input, &emit);
    }

    /// Bytes the query holds for sweep bounds of the whole scene (in_lo_x_ ... strip_hi_).
    static std::size_t scene_sweep_bytes(const pair_search& search) {
        return sizeof(float) * (search.in_lo_x_.capacity() + search.in_lo_y_.capacity() + search.in_hi_x_.capacity() +
                                search.in_hi_y_.capacity()) +
               sizeof(std::uint32_t) *
                   (search.q_lo_.capacity() + search.q_hi_.capacity() + search.strip_hi_.capacity());
    }

    static std::size_t strips(const pair_search& search) { return search.grid_.strips; }
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
    std::vector<std::uint64_t> categories(boxes.size()), masks(boxes.size());
    std::vector<std::int32_t> groups(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        categories[i] = std::uint64_t{1} << (i % 4);
        masks[i] = i % 8 == 0 ? ~std::uint64_t{2} : obbsat::all_categories;
        groups[i] = i % 16 == 0 ? static_cast<std::int32_t>(i % 3 + 1) : 0;
    }
    query_input input = rows_of(boxes);
    input.a_filters.categories = categories.data();
    input.a_filters.masks = masks.data();
    input.a_filters.groups = groups.data();
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
