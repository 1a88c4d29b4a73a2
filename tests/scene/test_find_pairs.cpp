// The scene queries (obbsat/find_pairs.hpp) against brute force over all
// pairs: for every method and store, the reported pairs are exactly those
// whose bounds (obbsat/ref/bounds.hpp) overlap and that the method's scalar
// reference calls colliding; for method exact, exactly the pairs the exact
// oracle calls colliding among all pairs. The same on every backend, thread
// count, entry point, and frame of a persistent query.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/ref/bounds.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_pose;

bool operator_less(const pair_index& x, const pair_index& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() &&
           std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

std::string describe_difference(const std::vector<pair_index>& got, const std::vector<pair_index>& want) {
    std::vector<pair_index> extra, missing;
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra), operator_less);
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing), operator_less);
    std::string text = std::to_string(got.size()) + " pairs against " + std::to_string(want.size()) + "; " +
                       std::to_string(extra.size()) + " extra, " + std::to_string(missing.size()) + " missing";
    if (!extra.empty()) {
        text += "; first extra (" + std::to_string(extra[0].a) + ", " + std::to_string(extra[0].b) + ")";
    }
    if (!missing.empty()) {
        text += "; first missing (" + std::to_string(missing[0].a) + ", " + std::to_string(missing[0].b) + ")";
    }
    return text;
}

#define EXPECT_SAME_PAIRS(got, want) EXPECT_TRUE(same_pairs(got, want)) << describe_difference(got, want)

template <class Box, class Reference>
std::vector<pair_index> brute_force(const std::vector<Box>& boxes, Reference reference, bool only_overlapping_bounds) {
    std::vector<obbsat::ref::box_bounds> bounds;
    for (const Box& b : boxes) {
        bounds.push_back(obbsat::ref::bounds_of(b));
    }
    std::vector<pair_index> out;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
            if (only_overlapping_bounds && !obbsat::ref::bounds_overlap(bounds[i], bounds[j])) {
                continue;
            }
            if (reference(boxes[i], boxes[j])) {
                out.push_back(pair_index{i, j});
            }
        }
    }
    return out;
}

template <class Box, class Reference>
std::vector<pair_index> brute_force_across(const std::vector<Box>& a, const std::vector<Box>& b, Reference reference) {
    std::vector<pair_index> out;
    for (std::uint32_t i = 0; i < a.size(); ++i) {
        const auto bi = obbsat::ref::bounds_of(a[i]);
        for (std::uint32_t j = 0; j < b.size(); ++j) {
            if (obbsat::ref::bounds_overlap(bi, obbsat::ref::bounds_of(b[j])) && reference(a[i], b[j])) {
                out.push_back(pair_index{i, j});
            }
        }
    }
    return out;
}

collide_options options_for(method m, obbsat::backend use = obbsat::backend::automatic, unsigned threads = 1) {
    collide_options o;
    o.test = m;
    o.use = use;
    o.threads = threads;
    return o;
}


// Scenes.

std::vector<rect_pose> seeded_scene(std::size_t boxes, obbsat::scene_sizes sizes, std::uint64_t seed,
                                    double origin = 0, double pairs_per_box = 3.0) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.sizes = sizes;
    spec.seed = seed;
    spec.origin_x = origin;
    spec.origin_y = -origin;
    spec.pairs_per_box = pairs_per_box;
    return obbsat::make_pose_scene(spec);
}

/// Squares of side 10 rotated by the vector (3, 4) (length 5, so every value
/// is an exact integer), on the lattice that makes each touch its eight
/// neighbours exactly along edges and at corners; then the same squares
/// axis-aligned with half extent 0.5 on the integer lattice.
std::vector<rect_pose> exact_tiles() {
    std::vector<rect_pose> out;
    for (int i = 0; i < 25; ++i) {
        for (int j = 0; j < 25; ++j) {
            const float x = static_cast<float>(6 * i - 8 * j);
            const float y = static_cast<float>(8 * i + 6 * j);
            out.push_back(rect_pose{{x, y}, {1.0f, 1.0f}, {3.0f, 4.0f}});
        }
    }
    for (int i = 0; i < 25; ++i) {
        for (int j = 0; j < 25; ++j) {
            out.push_back(rect_pose{{500.0f + static_cast<float>(i), static_cast<float>(j)}, {0.5f, 0.5f}, {1.0f, 0.0f}});
        }
    }
    return out;
}

/// Zero-width and zero-size rectangles (segments and points) among thin ones.
std::vector<rect_pose> slivers() {
    obbsat::seeded_random random(77);
    std::vector<rect_pose> out;
    for (int k = 0; k < 1500; ++k) {
        const float t = random.uniform(-1.0f, 1.0f);
        const float hy = k % 3 == 0 ? 0.0f : random.uniform(0.0f, 1e-3f);
        const float hx = k % 7 == 0 ? 0.0f : random.uniform(0.0f, 3.0f);
        out.push_back(rect_pose{{random.uniform(0.0f, 60.0f), random.uniform(0.0f, 60.0f)},
                                {hx, hy},
                                {(1.0f - t * t) / (1.0f + t * t), 2.0f * t / (1.0f + t * t)}});
    }
    return out;
}

struct named_scene {
    std::string name;
    std::vector<rect_pose> poses;
};

std::vector<named_scene> hard_scenes() {
    std::vector<named_scene> out;
    out.push_back({"uniform", seeded_scene(2000, obbsat::scene_sizes::uniform, 1)});
    out.push_back({"mixed", seeded_scene(2000, obbsat::scene_sizes::mixed, 2)});
    out.push_back({"far", seeded_scene(2000, obbsat::scene_sizes::uniform, 3, 3e6)});
    out.push_back({"far_mixed", seeded_scene(1500, obbsat::scene_sizes::mixed, 4, 2e7)});
    out.push_back({"tiles", exact_tiles()});
    out.push_back({"slivers", slivers()});
    std::vector<rect_pose> tiny = seeded_scene(1000, obbsat::scene_sizes::uniform, 5);
    for (rect_pose& p : tiny) {
        p.center = {p.center.x * 1e-30f, p.center.y * 1e-30f};
        p.half_extents = {p.half_extents.x * 1e-30f, p.half_extents.y * 1e-30f};
    }
    out.push_back({"tiny", tiny});
    return out;
}

std::vector<rect> corners_of_scene(const std::vector<rect_pose>& poses) {
    const obbsat::rect_records records = obbsat::corner_records_of(obbsat::pose_records(poses));
    return std::vector<rect>(records.data(), records.data() + records.size());
}

// The rule, every method, every store, every hard scene.

TEST(find_pairs, poses_report_exactly_the_overlapping_bounds_the_method_calls_colliding) {
    for (const named_scene& scene : hard_scenes()) {
        const obbsat::pose_records store(scene.poses);
        for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
            const auto want = brute_force(scene.poses, obbsat::pose_method_reference(m), true);
            const auto got = obbsat::find_pairs(store, options_for(m));
            SCOPED_TRACE(scene.name + " / " + obbsat::method_name(m));
            EXPECT_SAME_PAIRS(got, want);
        }
    }
}

TEST(find_pairs, corners_report_exactly_the_overlapping_bounds_the_method_calls_colliding) {
    for (const named_scene& scene : hard_scenes()) {
        const std::vector<rect> rects = corners_of_scene(scene.poses);
        const obbsat::rect_records store(rects);
        for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
            const auto want = brute_force(rects, obbsat::method_reference(m), true);
            const auto got = obbsat::find_pairs(store, options_for(m));
            SCOPED_TRACE(scene.name + " / " + obbsat::method_name(m));
            EXPECT_SAME_PAIRS(got, want);
        }
    }
}

TEST(find_pairs, exact_equals_the_oracle_on_every_pair_of_the_scene) {
    // No bounds in the brute force: the broadphase must lose no colliding pair.
    for (const named_scene& scene : hard_scenes()) {
        const auto want = brute_force(scene.poses, obbsat::pose_method_reference(method::exact), false);
        const auto got = obbsat::find_pairs(obbsat::pose_records(scene.poses), options_for(method::exact));
        SCOPED_TRACE(scene.name);
        EXPECT_SAME_PAIRS(got, want);
        const std::vector<rect> rects = corners_of_scene(scene.poses);
        const auto want_corners = brute_force(rects, obbsat::method_reference(method::exact), false);
        EXPECT_SAME_PAIRS(obbsat::find_pairs(obbsat::rect_records(rects), options_for(method::exact)), want_corners);
    }
}

TEST(find_pairs, conservative_contains_every_colliding_pair) {
    for (const named_scene& scene : hard_scenes()) {
        const auto exact = brute_force(scene.poses, obbsat::pose_method_reference(method::exact), false);
        const auto got = obbsat::find_pairs(obbsat::pose_records(scene.poses), options_for(method::conservative));
        SCOPED_TRACE(scene.name);
        EXPECT_TRUE(std::includes(got.begin(), got.end(), exact.begin(), exact.end(), operator_less));
    }
}

TEST(find_pairs, the_tiles_touch_their_eight_neighbours) {
    // A check of the scene itself, so that the tiles test what they claim.
    const std::vector<rect_pose> tiles = exact_tiles();
    const auto got = obbsat::find_pairs(obbsat::pose_records(tiles), options_for(method::exact));
    // Per 25 x 25 lattice: 2·25·24 edge neighbours and 2·24·24 corner neighbours.
    EXPECT_EQ(got.size(), 2u * (2 * 25 * 24 + 2 * 24 * 24));
}

TEST(find_pairs, twenty_thousand_boxes_equal_brute_force) {
    for (const obbsat::scene_sizes sizes : {obbsat::scene_sizes::uniform, obbsat::scene_sizes::mixed}) {
        const auto poses = seeded_scene(20000, sizes, 11, 0, 2.0);
        const auto want = brute_force(poses, obbsat::pose_method_reference(method::exact), true);
        const auto got = obbsat::find_pairs(obbsat::pose_records(poses), options_for(method::exact));
        SCOPED_TRACE(obbsat::scene_sizes_name(sizes));
        EXPECT_SAME_PAIRS(got, want);
        EXPECT_GT(got.size(), 20000u);  // the scene is as dense as asked (about 2 per box)
        EXPECT_LT(got.size(), 60000u);
    }
}

// Backends, threads, entry points.

TEST(find_pairs, every_backend_and_thread_count_gives_the_same_pairs) {
    // Large enough that two threads split the sweep.
    const auto poses = seeded_scene(60000, obbsat::scene_sizes::mixed, 21, 0, 2.0);
    const obbsat::pose_records store(poses);
    const std::vector<rect> rects = corners_of_scene(poses);
    const obbsat::rect_records corners(rects);
    for (const method m : {method::exact, method::local}) {
        const auto baseline = obbsat::find_pairs(store, options_for(m, obbsat::backend::scalar, 1));
        for (const obbsat::backend b : obbsat::runnable_backends()) {
            for (const unsigned threads : {1u, 2u, 0u}) {
                SCOPED_TRACE(std::string(obbsat::backend_name(b)) + " threads " + std::to_string(threads) + " " +
                             obbsat::method_name(m));
                EXPECT_SAME_PAIRS(obbsat::find_pairs(store, options_for(m, b, threads)), baseline);
            }
        }
    }
    const auto corner_baseline = obbsat::find_pairs(corners, options_for(method::sat4, obbsat::backend::scalar, 1));
    for (const obbsat::backend b : obbsat::runnable_backends()) {
        EXPECT_SAME_PAIRS(obbsat::find_pairs(corners, options_for(method::sat4, b, 2)), corner_baseline);
    }
}

// A mixed scene with visits enough to merge its near and far visits in
// shares (16384 visits a share): on two to four threads, the pairs of one.
TEST(find_pairs, visits_merged_in_shares_give_the_pairs_of_one_thread) {
    const auto poses = seeded_scene(200000, obbsat::scene_sizes::mixed, 23, 0, 2.0);
    const obbsat::pose_records store(poses);
    obbsat::pair_finder one(options_for(method::exact, obbsat::backend::automatic, 1));
    const std::vector<obbsat::pair_index> baseline = one.find(store);
    ASSERT_GT(one.stats().visits, 4u * 16384u);
    for (const unsigned threads : {2u, 3u, 4u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        EXPECT_SAME_PAIRS(obbsat::find_pairs(store, options_for(method::exact, obbsat::backend::automatic, threads)),
                          baseline);
    }
}

TEST(find_pairs, streaming_gives_each_pair_once) {
    const auto poses = seeded_scene(40000, obbsat::scene_sizes::uniform, 31, 0, 2.0);
    const obbsat::pose_records store(poses);
    const auto want = obbsat::find_pairs(store, options_for(method::exact));
    std::vector<pair_index> streamed;
    std::size_t calls = 0;
    obbsat::find_pairs_each(store, options_for(method::exact, obbsat::backend::automatic, 2),
                            [&](const pair_index* pairs, std::size_t count) {
                                streamed.insert(streamed.end(), pairs, pairs + count);
                                ++calls;
                            });
    std::sort(streamed.begin(), streamed.end(), operator_less);
    EXPECT_SAME_PAIRS(streamed, want);
    EXPECT_GT(calls, 1u);  // in chunks, not all at once
}

TEST(find_pairs, an_exception_from_the_sink_reaches_the_caller) {
    const auto poses = seeded_scene(40000, obbsat::scene_sizes::uniform, 32, 0, 2.0);
    const obbsat::pose_records store(poses);
    EXPECT_THROW(obbsat::find_pairs_each(store, options_for(method::local, obbsat::backend::automatic, 2),
                                         [](const pair_index*, std::size_t) { throw std::runtime_error("full"); }),
                 std::runtime_error);
}

TEST(find_pairs, slow_path_pairs_are_reported) {
    const std::vector<rect_pose> tiles = exact_tiles();
    std::size_t slow = 12345;
    collide_options o = options_for(method::exact);
    o.slow_path_pairs = &slow;
    obbsat::find_pairs(obbsat::pose_records(tiles), o);
    EXPECT_GT(slow, 0u);  // exact contacts cannot be certified by the float filter
    EXPECT_NE(slow, 12345u);
}

// Two stores.

TEST(find_pairs, across_two_stores_equals_brute_force) {
    const auto a = seeded_scene(1500, obbsat::scene_sizes::mixed, 41, 0, 2.0);
    auto b = seeded_scene(1200, obbsat::scene_sizes::uniform, 42, 0, 2.0);
    for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
        const auto want = brute_force_across(a, b, obbsat::pose_method_reference(m));
        const auto got = obbsat::find_pairs(obbsat::pose_records(a), obbsat::pose_records(b), options_for(m));
        SCOPED_TRACE(obbsat::method_name(m));
        EXPECT_SAME_PAIRS(got, want);
    }
    const std::vector<rect> ra = corners_of_scene(a);
    const std::vector<rect> rb = corners_of_scene(b);
    const auto want = brute_force_across(ra, rb, obbsat::method_reference(method::sat4));
    EXPECT_SAME_PAIRS(obbsat::find_pairs(obbsat::rect_records(ra), obbsat::rect_records(rb), options_for(method::sat4)),
                      want);
}

TEST(find_pairs, across_a_store_and_itself_reports_both_orders_and_the_diagonal) {
    const auto a = seeded_scene(500, obbsat::scene_sizes::uniform, 43);
    const obbsat::pose_records store(a);
    const auto within = obbsat::find_pairs(store, options_for(method::exact));
    const auto across = obbsat::find_pairs(store, store, options_for(method::exact));
    // Every rectangle meets itself; each pair within appears as (i, j) and (j, i).
    EXPECT_EQ(across.size(), a.size() + 2 * within.size());
}

TEST(find_pairs, empty_and_single_stores_have_no_pairs) {
    const obbsat::pose_records none;
    const obbsat::pose_records one(std::vector<rect_pose>{rect_pose{{0, 0}, {1, 1}, {1, 0}}});
    EXPECT_TRUE(obbsat::find_pairs(none, options_for(method::exact)).empty());
    EXPECT_TRUE(obbsat::find_pairs(one, options_for(method::exact)).empty());
    EXPECT_TRUE(obbsat::find_pairs(none, one, options_for(method::exact)).empty());
    EXPECT_TRUE(obbsat::find_pairs(one, none, options_for(method::exact)).empty());
    EXPECT_EQ(obbsat::find_pairs(one, one, options_for(method::exact)).size(), 1u);
    EXPECT_TRUE(obbsat::find_pairs(obbsat::rect_records(), options_for(method::sat4)).empty());
}

TEST(find_pairs, every_box_in_one_place_is_every_pair) {
    std::vector<rect_pose> stack(300, rect_pose{{5, 5}, {1, 2}, {0.6f, 0.8f}});
    const auto got = obbsat::find_pairs(obbsat::pose_records(stack), options_for(method::exact, obbsat::backend::automatic, 2));
    EXPECT_EQ(got.size(), 300u * 299u / 2u);
}

TEST(find_pairs, boxes_whose_bounds_overflow_still_meet_everything_they_touch) {
    auto poses = seeded_scene(500, obbsat::scene_sizes::uniform, 51);
    // Bounds infinite on every side, first in the sweep's order and last, and a
    // box alone: the sweep must take no padding past a strip's last entry.
    const rect_pose everywhere{{0, 0}, {3e38f, 3e38f}, {2.0f, 2.0f}};
    const obbsat::ref::box_bounds b = obbsat::ref::bounds_of(everywhere);
    ASSERT_TRUE(std::isinf(b.lo_x) && std::isinf(b.lo_y) && std::isinf(b.hi_x) && std::isinf(b.hi_y));
    poses.insert(poses.begin(), everywhere);
    poses.push_back(everywhere);
    const auto want = brute_force(poses, obbsat::pose_method_reference(method::exact), false);
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        SCOPED_TRACE(obbsat::backend_name(use));
        EXPECT_SAME_PAIRS(obbsat::find_pairs(poses, options_for(method::exact, use)), want);
        const std::vector<rect_pose> alone{everywhere};
        EXPECT_TRUE(obbsat::find_pairs(alone, options_for(method::exact, use)).empty());
        const std::vector<rect_pose> two{everywhere, poses[3]};
        EXPECT_SAME_PAIRS(obbsat::find_pairs(two, options_for(method::exact, use)), (std::vector<pair_index>{{0, 1}}));
    }
}

// Errors.

TEST(find_pairs, a_method_that_does_not_run_on_the_store_is_refused) {
    const obbsat::pose_records poses(seeded_scene(10, obbsat::scene_sizes::uniform, 1));
    try {
        obbsat::find_pairs(poses, options_for(method::sat4));
        FAIL() << "sat4 on poses was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("sat4 does not run on poses"), std::string::npos) << e.what();
    }
    EXPECT_THROW(obbsat::find_pairs(obbsat::rect_records(), options_for(method::local)), obbsat::invalid_input);
    collide_options bad;
    bad.test = static_cast<method>(99);
    EXPECT_THROW(obbsat::find_pairs(poses, bad), obbsat::invalid_input);
    obbsat::pair_finder finder(bad);
    EXPECT_THROW(finder.find(poses), obbsat::invalid_input);
}

// Rows in the caller's memory.

TEST(find_pairs, rows_in_place_give_the_pairs_of_the_stores) {
    const auto poses = seeded_scene(20000, obbsat::scene_sizes::mixed, 91, 0, 2.0);
    const auto corners = corners_of_scene(poses);
    const obbsat::pose_records pose_store(poses);
    const obbsat::rect_records corner_store(corners);
    for (const method m : {method::exact, method::local, method::conservative}) {
        SCOPED_TRACE(obbsat::method_name(m));
        EXPECT_SAME_PAIRS(obbsat::find_pairs(poses, options_for(m)), obbsat::find_pairs(pose_store, options_for(m)));
    }
    for (const method m : {method::exact, method::sat4}) {
        SCOPED_TRACE(obbsat::method_name(m));
        EXPECT_SAME_PAIRS(obbsat::find_pairs(corners, options_for(m)),
                          obbsat::find_pairs(corner_store, options_for(m)));
    }
    // A cross query with rows on one side and a store on the other, both ways.
    const std::vector<rect_pose> first(poses.begin(), poses.begin() + 8000);
    const obbsat::pose_records second(std::vector<rect_pose>(poses.begin() + 8000, poses.end()));
    const auto want = obbsat::find_pairs(obbsat::pose_records(first), second, options_for(method::exact, {}, 2));
    EXPECT_SAME_PAIRS(obbsat::find_pairs(first, second, options_for(method::exact, {}, 2)), want);
    EXPECT_SAME_PAIRS(obbsat::find_pairs(obbsat::box_view(poses.data(), 8000), second, options_for(method::exact)),
                      want);
    // A frame sequence over rows: every frame equals a fresh query over a store.
    auto moving = poses;
    obbsat::pair_finder finder(options_for(method::exact));
    obbsat::seeded_random random(92);
    for (int frame = 0; frame < 4; ++frame) {
        EXPECT_SAME_PAIRS(finder.find(moving), obbsat::find_pairs(obbsat::pose_records(moving), options_for(method::exact)))
            << "frame " << frame;
        for (rect_pose& p : moving) {
            p.center.x += random.uniform(-0.1f, 0.1f);
        }
    }
}

TEST(find_pairs, a_bad_row_is_refused_by_name_and_nothing_is_reported) {
    auto poses = seeded_scene(40000, obbsat::scene_sizes::uniform, 93, 0, 2.0);
    auto corners = corners_of_scene(poses);
    const auto refused = [](const std::function<void()>& query, const std::string& text) {
        try {
            query();
            ADD_FAILURE() << "accepted; expected: " << text;
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        }
    };
    std::size_t emitted = 0;
    const obbsat::pair_chunk_sink count_them = [&](const pair_index*, std::size_t k) { emitted += k; };
    // Two bad rows: the first is named, whichever thread reads it.
    poses[30001].half_extents.y = -1.0f;
    poses[15001].rotation = {0.0f, 0.0f};
    for (const unsigned threads : {1u, 2u}) {
        refused([&] { obbsat::find_pairs(poses, options_for(method::exact, {}, threads)); },
                "pose 15001: rotation vector (c, s) is (0, 0)");
        refused([&] { obbsat::find_pairs_each(poses, options_for(method::exact, {}, threads), count_them); },
                "pose 15001");
    }
    poses[15001].rotation = {1.0f, 0.0f};
    refused([&] { obbsat::find_pairs(poses, options_for(method::exact)); }, "pose 30001: half extent hy is -1");
    poses[30001].half_extents.y = 1.0f;
    poses[7].center.x = std::numeric_limits<float>::quiet_NaN();
    const std::vector<rect_pose> a(poses.begin() + 5, poses.begin() + 10);
    refused([&] { obbsat::find_pairs(a, poses, options_for(method::exact)); }, "a: pose 2:");
    refused([&] { obbsat::find_pairs(obbsat::pose_records(a.data(), 1), poses,
                                     options_for(method::exact)); }, "b: pose 7:");
    obbsat::pair_finder finder(options_for(method::exact));
    refused([&] { finder.find(poses); }, "pose 7:");
    corners[12].lr.y = std::numeric_limits<float>::infinity();
    refused([&] { obbsat::find_pairs(corners, options_for(method::exact)); }, "rectangle 12: coordinate lry is not finite");
    EXPECT_EQ(emitted, 0u);
    // One kind per query.
    refused([&] { obbsat::find_pairs(obbsat::pose_records(a.data(), 1), obbsat::rect_records(),
                                     options_for(method::exact)); }, "one kind");
}

// A persistent query over frames.

TEST(pair_finder, every_frame_equals_a_fresh_query) {
    auto poses = seeded_scene(30000, obbsat::scene_sizes::mixed, 61, 0, 2.0);
    obbsat::pair_finder finder(options_for(method::exact, obbsat::backend::automatic, 2));
    obbsat::seeded_random random(62);
    std::size_t reused = 0;
    for (int frame = 0; frame < 12; ++frame) {
        const obbsat::pose_records store(poses);
        const std::vector<pair_index> got = finder.find(store);
        EXPECT_SAME_PAIRS(got, obbsat::find_pairs(store, options_for(method::exact))) << "frame " << frame;
        reused += finder.stats().reused_order ? 1u : 0u;
        EXPECT_EQ(finder.stats().pairs, got.size());
        EXPECT_GT(finder.stats().kernel_seconds, 0.0);
        EXPECT_LE(finder.stats().kernel_seconds, 2.0 * finder.stats().sweep_seconds + 1e-3);  // two threads at most
        for (rect_pose& p : poses) {
            p.center.x += random.uniform(-0.1f, 0.1f);
            p.center.y += random.uniform(-0.1f, 0.1f);
        }
    }
    // Small motion repairs the last order or keeps the candidates; a full query
    // whose widening changed may sort anew.
    EXPECT_GE(reused, 9u);
    // A different scene through the same object: a fresh order, the right answer.
    const obbsat::pose_records other(seeded_scene(5000, obbsat::scene_sizes::uniform, 63));
    EXPECT_SAME_PAIRS(finder.find(other), obbsat::find_pairs(other, options_for(method::exact)));
    EXPECT_FALSE(finder.stats().reused_order);
}

/// The scene after `frame` frames of steady motion: each box drifts by its
/// own velocity, up to `speed` per frame in each axis, and turns a little.
std::vector<rect_pose> drifted(const std::vector<rect_pose>& start, int frame, float speed, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<rect_pose> out = start;
    const float t = static_cast<float>(frame);
    for (rect_pose& p : out) {
        const float vx = random.uniform(-speed, speed);
        const float vy = random.uniform(-speed, speed);
        const float turn = random.uniform(-0.01f, 0.01f) * t;
        p.center = {p.center.x + vx * t, p.center.y + vy * t};
        const float c = std::cos(turn), s = std::sin(turn);
        p.rotation = {p.rotation.x * c - p.rotation.y * s, p.rotation.x * s + p.rotation.y * c};
    }
    return out;
}

/// The typical half extent of a scene, for motion at its scale.
float typical_size(const std::vector<rect_pose>& poses) {
    std::vector<float> sizes;
    for (const rect_pose& p : poses) {
        sizes.push_back(std::max(p.half_extents.x, p.half_extents.y));
    }
    std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
    return sizes[sizes.size() / 2];
}

// Frames answered from the kept candidates equal fresh queries: every method,
// both kinds of store, every hard scene, in steady motion (some frames from
// the kept candidates, some after a rectangle left its widened bounds) and
// in a scene that goes back and forth between two states (the exact contacts
// of the tiles come back in frames answered from kept candidates).
// Boxes that move further than their widened bounds every frame: each call
// runs the full query on the last order, repaired (from the sixth call, when
// the widening has grown to its largest and no longer changes the order).
// Those that changed strips, about a third, are sorted apart and merged in;
// the answer is a fresh query's on one to three threads.
TEST(pair_finder, a_repaired_order_with_boxes_that_changed_strips_answers_as_a_fresh_query) {
    for (const unsigned threads : {1u, 2u, 3u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        auto poses = seeded_scene(60000, obbsat::scene_sizes::uniform, 71, 0, 2.0);
        obbsat::pair_finder finder(options_for(method::exact, obbsat::backend::automatic, threads));
        obbsat::seeded_random random(72);
        std::size_t full = 0, repaired = 0;
        for (int frame = 0; frame < 10; ++frame) {
            const obbsat::pose_records store(poses);
            const std::vector<pair_index> got = finder.find(store);
            EXPECT_SAME_PAIRS(got, obbsat::find_pairs(store, options_for(method::exact))) << "frame " << frame;
            if (frame >= 1) {
                full += finder.stats().reused_candidates ? 0u : 1u;
                repaired += finder.stats().reused_order ? 1u : 0u;
            }
            for (rect_pose& p : poses) {
                p.center.x += random.uniform(-1.5f, 1.5f);
                p.center.y += random.uniform(-1.5f, 1.5f);
            }
        }
        // Every frame is a full query. The second call (which keeps) and the
        // third (the miss that pauses keeping) repair the order; later paused
        // calls take a repair or a new sort, whichever they timed cheaper.
        EXPECT_EQ(full, 9u);
        EXPECT_GE(repaired, 2u);
    }
}

TEST(pair_finder, kept_candidates_answer_as_a_fresh_query_in_every_scene_and_method) {
    std::size_t from_kept = 0, rebuilt = 0;
    for (const named_scene& scene : hard_scenes()) {
        const float speed = 0.02f * typical_size(scene.poses);
        for (const bool back_and_forth : {false, true}) {
            std::vector<std::vector<rect_pose>> frames;
            for (int f = 0; f < 8; ++f) {
                frames.push_back(drifted(scene.poses, back_and_forth ? f % 2 : f, speed, 7));
            }
            for (const method m : obbsat::methods_on(obbsat::store_kind::poses)) {
                obbsat::pair_finder finder(options_for(m));
                for (std::size_t f = 0; f < frames.size(); ++f) {
                    const obbsat::pose_records store(frames[f]);
                    const std::vector<pair_index> got = finder.find(store);
                    SCOPED_TRACE(scene.name + " / " + obbsat::method_name(m) + " / frame " + std::to_string(f) +
                                 (back_and_forth ? " back and forth" : " steady"));
                    EXPECT_SAME_PAIRS(got, obbsat::find_pairs(store, options_for(m)));
                    from_kept += finder.stats().reused_candidates ? 1u : 0u;
                    rebuilt += finder.stats().reused_candidates ? 0u : 1u;
                    if (f == 0) {
                        // The first call answers as a plain query and keeps nothing.
                        EXPECT_FALSE(finder.stats().reused_candidates);
                        EXPECT_EQ(finder.stats().kept_candidates, 0u);
                    } else if (finder.stats().kept_paused) {
                        // Keeping paused after a miss: a plain query that keeps nothing.
                        EXPECT_FALSE(finder.stats().reused_candidates);
                        EXPECT_EQ(finder.stats().kept_candidates, 0u);
                    } else {
                        EXPECT_GE(finder.stats().kept_candidates, finder.stats().candidates);
                    }
                }
            }
            for (const method m : obbsat::methods_on(obbsat::store_kind::corners)) {
                obbsat::pair_finder finder(options_for(m));
                for (std::size_t f = 0; f < frames.size(); ++f) {
                    const std::vector<rect> rects = corners_of_scene(frames[f]);
                    SCOPED_TRACE(scene.name + " / corners / " + obbsat::method_name(m) + " / frame " +
                                 std::to_string(f));
                    EXPECT_SAME_PAIRS(finder.find(rects), obbsat::find_pairs(rects, options_for(m)));
                }
            }
        }
    }
    // Both ways of answering were taken, many times.
    EXPECT_GT(from_kept, 100u);
    EXPECT_GT(rebuilt, 50u);
}

TEST(pair_finder, kept_candidates_on_two_threads_and_across_stores) {
    const auto start = seeded_scene(40000, obbsat::scene_sizes::mixed, 64, 0, 2.0);
    const auto other = seeded_scene(3000, obbsat::scene_sizes::uniform, 65, 0, 2.0);
    obbsat::pair_finder finder(options_for(method::exact, obbsat::backend::automatic, 2));
    obbsat::pair_finder across(options_for(method::exact, obbsat::backend::automatic, 2));
    std::size_t from_kept = 0;
    for (int f = 0; f < 10; ++f) {
        const auto frame = drifted(start, f, 0.01f, 9);
        const auto moved_other = drifted(other, f, 0.03f, 10);
        EXPECT_SAME_PAIRS(finder.find(frame), obbsat::find_pairs(frame, options_for(method::exact))) << f;
        from_kept += finder.stats().reused_candidates ? 1u : 0u;
        EXPECT_SAME_PAIRS(across.find(moved_other, frame),
                          obbsat::find_pairs(moved_other, frame, options_for(method::exact)))
            << f;
        from_kept += across.stats().reused_candidates ? 1u : 0u;
    }
    EXPECT_GE(from_kept, 8u);
}

/// Runs `frames` frames of `start` drifting (0.01 a frame, seed `drift_seed`)
/// through one pair_finder per thread count, each frame's answer checked
/// against a fresh query; at least `from_kept` frames must be answered from
/// kept candidates.
void expect_kept_frames_equal_fresh_queries(const std::vector<rect_pose>& start,
                                            std::initializer_list<unsigned> thread_counts, int frames,
                                            std::uint64_t drift_seed, std::size_t from_kept) {
    for (const unsigned threads : thread_counts) {
        obbsat::pair_finder finder(options_for(method::exact, obbsat::backend::automatic, threads));
        std::size_t kept = 0;
        for (int f = 0; f < frames; ++f) {
            const auto frame = drifted(start, f, 0.01f, drift_seed);
            EXPECT_SAME_PAIRS(finder.find(frame), obbsat::find_pairs(frame, options_for(method::exact)))
                << threads << " threads, frame " << f;
            kept += finder.stats().reused_candidates ? 1u : 0u;
        }
        EXPECT_GE(kept, from_kept) << threads << " threads";
    }
}

// More threads than two: every share of the answer, the middle ones too, is
// written in place from the counts the test made of it.
TEST(pair_finder, kept_candidates_on_three_and_four_threads) {
    expect_kept_frames_equal_fresh_queries(seeded_scene(70000, obbsat::scene_sizes::uniform, 66, 0, 2.0), {3u, 4u}, 5,
                                           13, 3);
}

// A scene whose records outgrow the caches (more than 12 MiB of 32-byte
// records, store_bytes_from_dram): kept frames write the records past the
// cache, and their answers on one and two threads are still a fresh query's.
TEST(pair_finder, kept_candidates_of_a_scene_larger_than_the_caches) {
    expect_kept_frames_equal_fresh_queries(seeded_scene(400000, obbsat::scene_sizes::uniform, 69, 0, 2.0), {1u, 2u}, 4,
                                           15, 2);
}

// The smallest boxes of a mixed scene are widened by a share of the scene's
// typical extent, which the first call measures though it keeps nothing: a
// scene going back and forth by more than a small box's own extent is
// answered from kept pairs from the third call on.
TEST(pair_finder, small_boxes_of_a_mixed_scene_are_widened_from_the_second_call) {
    const auto start = seeded_scene(20000, obbsat::scene_sizes::mixed, 68, 0, 2.0);
    const auto moved = drifted(start, 1, 0.02f * typical_size(start), 14);
    obbsat::pair_finder finder(options_for(method::exact));
    finder.find(start);
    EXPECT_EQ(finder.stats().kept_candidates, 0u);
    finder.find(moved);
    EXPECT_GT(finder.stats().kept_candidates, 0u);
    for (int f = 0; f < 4; ++f) {
        const auto& frame = f % 2 == 0 ? start : moved;
        EXPECT_SAME_PAIRS(finder.find(frame), obbsat::find_pairs(frame, options_for(method::exact))) << f;
        EXPECT_TRUE(finder.stats().reused_candidates) << f;
    }
}

// One huge box among small ones widens only itself: the kept pairs stay a
// few per box instead of every small box meeting every other.
TEST(pair_finder, a_huge_box_does_not_widen_the_others) {
    auto start = seeded_scene(20000, obbsat::scene_sizes::uniform, 67, 0, 2.0);
    start.push_back(rect_pose{{0.0f, 0.0f}, {1e7f, 1e7f}, {1.0f, 0.0f}});
    start.push_back(rect_pose{{3e8f, 3e8f}, {1e8f, 1e8f}, {0.6f, 0.8f}});
    obbsat::pair_finder finder(options_for(method::exact));
    std::size_t from_kept = 0;
    for (int f = 0; f < 8; ++f) {
        const auto frame = drifted(start, f, 0.01f, 11);
        EXPECT_SAME_PAIRS(finder.find(frame), obbsat::find_pairs(frame, options_for(method::exact))) << f;
        from_kept += finder.stats().reused_candidates ? 1u : 0u;
        EXPECT_LT(finder.stats().kept_candidates, 3 * finder.stats().candidates + 2 * start.size()) << f;
    }
    EXPECT_GE(from_kept, 4u);
}

// Dense specks among as many huge boxes: the typical extent is huge, so the
// widened specks would meet every other speck. The finder stays within its
// budget of kept pairs and answers as a plain query.
TEST(pair_finder, widened_bounds_that_meet_too_many_are_not_kept) {
    std::vector<rect_pose> start;
    for (int i = 0; i < 55; ++i) {
        for (int j = 0; j < 55; ++j) {
            start.push_back(rect_pose{{0.01f * static_cast<float>(i), 0.01f * static_cast<float>(j)},
                                      {0.001f, 0.001f}, {1.0f, 0.0f}});
        }
    }
    const std::size_t specks = start.size();
    for (std::size_t k = 0; k <= specks; ++k) {
        start.push_back(rect_pose{{1e4f + 1000.0f * static_cast<float>(k % 60), 1000.0f * static_cast<float>(k / 60)},
                                  {50.0f, 50.0f}, {0.6f, 0.8f}});
    }
    obbsat::pair_finder finder(options_for(method::exact));
    std::size_t plain_after_first = 0;
    for (int f = 0; f < 6; ++f) {
        const auto frame = drifted(start, f, 0.002f, 12);
        EXPECT_SAME_PAIRS(finder.find(frame), obbsat::find_pairs(frame, options_for(method::exact))) << f;
        EXPECT_LE(finder.stats().kept_candidates, 4 * finder.stats().candidates + 2 * start.size()) << f;
        plain_after_first += f > 0 && finder.stats().kept_candidates == 0 ? 1u : 0u;
    }
    EXPECT_GE(plain_after_first, 1u);  // a call past its budget answered as a plain query
}

TEST(pair_finder, a_box_that_jumps_and_a_bad_row_are_handled_between_kept_frames) {
    auto poses = seeded_scene(20000, obbsat::scene_sizes::uniform, 66, 0, 2.0);
    obbsat::pair_finder finder(options_for(method::exact));
    finder.find(poses);
    for (rect_pose& p : poses) {
        p.center.x += 0.01f;
    }
    finder.find(poses);  // built with widened bounds
    poses[1].center.x += 0.01f;
    EXPECT_SAME_PAIRS(finder.find(poses), obbsat::find_pairs(poses, options_for(method::exact)));
    EXPECT_TRUE(finder.stats().reused_candidates);
    // A box lands on another far away: its bounds left the widened ones.
    poses[3].center = poses[19000].center;
    EXPECT_SAME_PAIRS(finder.find(poses), obbsat::find_pairs(poses, options_for(method::exact)));
    EXPECT_FALSE(finder.stats().reused_candidates);
    const auto with_jump = finder.find(poses);
    EXPECT_TRUE(finder.stats().reused_candidates);
    EXPECT_TRUE(std::binary_search(with_jump.begin(), with_jump.end(), pair_index{3, 19000}, operator_less));
    // A bad row between kept frames is refused by name, as a fresh query refuses it.
    poses[7].half_extents.x = -2.0f;
    try {
        finder.find(poses);
        ADD_FAILURE() << "a negative half extent was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pose 7: half extent hx is -2"), std::string::npos) << e.what();
    }
    poses[7].half_extents.x = 1.0f;
    EXPECT_SAME_PAIRS(finder.find(poses), obbsat::find_pairs(poses, options_for(method::exact)));
}

TEST(pair_finder, a_scene_that_moves_far_gets_a_new_layout_and_the_right_pairs) {
    auto poses = seeded_scene(20000, obbsat::scene_sizes::uniform, 71, 0, 2.0);
    obbsat::pair_finder finder(options_for(method::local));
    finder.find(obbsat::pose_records(poses));
    for (rect_pose& p : poses) {
        p.center = {p.center.y * 3.0f + 1e4f, p.center.x * 0.5f};
    }
    const obbsat::pose_records moved(poses);
    EXPECT_SAME_PAIRS(finder.find(moved), obbsat::find_pairs(moved, options_for(method::local)));
}

TEST(pair_finder, works_across_stores_and_kinds) {
    const auto a = seeded_scene(3000, obbsat::scene_sizes::uniform, 81);
    const auto b = seeded_scene(3000, obbsat::scene_sizes::mixed, 82);
    obbsat::pair_finder finder(options_for(method::exact));
    const obbsat::pose_records pa(a), pb(b);
    EXPECT_SAME_PAIRS(finder.find(pa, pb), obbsat::find_pairs(pa, pb, options_for(method::exact)));
    const obbsat::rect_records ra(corners_of_scene(a));
    EXPECT_SAME_PAIRS(finder.find(ra), obbsat::find_pairs(ra, options_for(method::exact)));
    EXPECT_SAME_PAIRS(finder.find(pa), obbsat::find_pairs(pa, options_for(method::exact)));
}

}  // namespace
