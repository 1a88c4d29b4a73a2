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

/// Expects `query` to throw invalid_input whose message holds `text`.
void expect_refused(const std::function<void()>& query, const std::string& text) {
    try {
        query();
        ADD_FAILURE() << "accepted; expected: " << text;
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
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
