// The scene queries (obbsat/find_pairs.hpp) at their limits: a scene so
// crowded that every pair collides, streamed in chunks no larger than the
// header promises; a pair_finder moved from; and queries with nothing to
// compare, which check their rows as larger ones do.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_pose;

collide_options options_for(method m, unsigned threads = 1) {
    collide_options o;
    o.test = m;
    o.threads = threads;
    return o;
}

/// The most pairs find_pairs_each hands to its sink at once (find_pairs.hpp).
constexpr std::size_t chunk_bound = 4096;

/// Expects `query` to throw invalid_input whose message holds `text`.
void expect_refused(const std::function<void()>& query, const std::string& text) {
    try {
        query();
        ADD_FAILURE() << "accepted; expected: " << text;
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

// A crowded scene: every box in one place, every pair colliding, all of them
// in one strip.

TEST(find_pairs_each, a_crowded_scene_streams_every_pair_in_bounded_chunks) {
    constexpr std::size_t n = 3000;
    const std::vector<rect_pose> stack(n, rect_pose{{0, 0}, {1, 1}, {1, 0}});
    const obbsat::pose_records store(stack);
    for (const unsigned threads : {1u, 2u}) {
        for (const bool rows : {false, true}) {
            SCOPED_TRACE(std::to_string(threads) + " threads, " + (rows ? "rows" : "store"));
            std::size_t total = 0;
            std::size_t largest = 0;
            std::size_t chunks = 0;
            std::vector<std::uint32_t> per_first(n, 0);
            const obbsat::pair_chunk_sink sink = [&](const pair_index* pairs, std::size_t count) {
                total += count;
                largest = std::max(largest, count);
                ++chunks;
                for (std::size_t k = 0; k < count; ++k) {
                    ++per_first[pairs[k].a];
                }
            };
            if (rows) {
                obbsat::find_pairs_each(stack, options_for(method::exact, threads), sink);
            } else {
                obbsat::find_pairs_each(store, options_for(method::exact, threads), sink);
            }
            EXPECT_EQ(total, n * (n - 1) / 2);
            EXPECT_LE(largest, chunk_bound) << "in " << chunks << " chunks";
            // Box i is the first of a pair with every later box: each pair once.
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(per_first[i], n - 1 - i) << "box " << i;
            }
        }
    }
}

TEST(find_pairs_each, a_crowded_scene_across_two_sets_streams_in_bounded_chunks) {
    const std::vector<rect> a(1500, rect{{-1, 1}, {1, 1}, {1, -1}, {-1, -1}});
    const std::vector<rect> b(1200, rect{{-1, 1}, {1, 1}, {1, -1}, {-1, -1}});
    std::size_t total = 0;
    std::size_t largest = 0;
    obbsat::find_pairs_each(a, b, options_for(method::sat4, 2), [&](const pair_index*, std::size_t count) {
        total += count;
        largest = std::max(largest, count);
    });
    EXPECT_EQ(total, a.size() * b.size());
    EXPECT_LE(largest, chunk_bound);
}

// A moved-from pair_finder.

TEST(pair_finder, a_moved_from_finder_refuses_every_call_with_a_clear_error) {
    const std::vector<rect_pose> poses{{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1, 0}}};
    obbsat::pair_finder finder(options_for(method::exact));
    ASSERT_EQ(finder.find(poses).size(), 1u);
    obbsat::pair_finder taker(std::move(finder));
    EXPECT_EQ(taker.find(poses).size(), 1u);
    expect_refused([&] { finder.find(poses); }, "moved-from pair_finder");
    expect_refused([&] { finder.find(poses, poses); }, "moved-from pair_finder");
    expect_refused([&] { (void)finder.stats(); }, "moved-from pair_finder");
    // Assigned from, it is empty again; assigned to, it works.
    obbsat::pair_finder other(options_for(method::exact));
    other = std::move(taker);
    expect_refused([&] { taker.find(poses); }, "moved-from pair_finder");
    EXPECT_EQ(other.find(poses).size(), 1u);
    finder = obbsat::pair_finder(options_for(method::local));
    EXPECT_EQ(finder.find(poses).size(), 1u);
    EXPECT_EQ(finder.stats().pairs, 1u);
}

// Queries with nothing to compare still check every row.

TEST(find_pairs, one_row_is_checked_as_any_other) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<rect_pose> nan_row{{{nan, nan}, {nan, nan}, {nan, nan}}};
    const std::vector<rect_pose> negative{{{0, 0}, {-1, 1}, {1, 0}}};
    const std::vector<rect> infinite{{{0, 0}, {1, 0}, {1, std::numeric_limits<float>::infinity()}, {0, 1}}};
    const obbsat::pair_chunk_sink ignore = [](const pair_index*, std::size_t) {};
    for (const unsigned threads : {1u, 2u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const collide_options o = options_for(method::exact, threads);
        expect_refused([&] { obbsat::find_pairs(nan_row, o); }, "pose 0:");
        expect_refused([&] { obbsat::find_pairs(negative, o); }, "pose 0: half extent hx is -1");
        expect_refused([&] { obbsat::find_pairs_each(nan_row, o, ignore); }, "pose 0:");
        expect_refused([&] { obbsat::find_pairs_each(negative, o, ignore); }, "pose 0: half extent hx is -1");
        expect_refused([&] { obbsat::find_pairs(infinite, options_for(method::sat4, threads)); },
                       "rectangle 0: coordinate lry is not finite");
        obbsat::pair_finder finder(o);
        expect_refused([&] { finder.find(nan_row); }, "pose 0:");
        expect_refused([&] { finder.find(negative); }, "pose 0: half extent hx is -1");
        // A good row is still no pair.
        const std::vector<rect_pose> good{{{0, 0}, {1, 1}, {1, 0}}};
        EXPECT_TRUE(obbsat::find_pairs(good, o).empty());
        EXPECT_TRUE(finder.find(good).empty());
    }
}

TEST(find_pairs, rows_against_an_empty_set_are_checked) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<rect_pose> three_nan(3, rect_pose{{nan, nan}, {nan, nan}, {nan, nan}});
    const std::vector<rect_pose> none;
    const collide_options o = options_for(method::exact);
    const obbsat::pair_chunk_sink ignore = [](const pair_index*, std::size_t) {};
    expect_refused([&] { obbsat::find_pairs(three_nan, none, o); }, "a: pose 0:");
    expect_refused([&] { obbsat::find_pairs(none, three_nan, o); }, "b: pose 0:");
    expect_refused([&] { obbsat::find_pairs_each(three_nan, none, o, ignore); }, "a: pose 0:");
    expect_refused([&] { obbsat::find_pairs(obbsat::pose_records(), three_nan, o); }, "b: pose 0:");
    obbsat::pair_finder finder(o);
    expect_refused([&] { finder.find(none, three_nan); }, "b: pose 0:");
    // The first bad row is named, the good ones before it pass.
    std::vector<rect_pose> mixed(3, rect_pose{{0, 0}, {1, 1}, {1, 0}});
    mixed[2].half_extents.y = -2.0f;
    expect_refused([&] { obbsat::find_pairs(mixed, none, o); }, "a: pose 2: half extent hy is -2");
    expect_refused([&] { finder.find(none, mixed); }, "b: pose 2: half extent hy is -2");
    // Good rows against an empty set: no pair.
    mixed[2].half_extents.y = 2.0f;
    EXPECT_TRUE(obbsat::find_pairs(mixed, none, o).empty());
    EXPECT_TRUE(finder.find(none, mixed).empty());
}

}  // namespace
