// Pair filters of the scene queries (obbsat/pair_filters.hpp): with random
// categories, masks and groups, every entry point reports exactly the pairs
// of the same query without filters that the filter rule lets through (the
// rule written here again, apart from the library's), for one set and
// across two, on one and two threads, for the exact method and a float one;
// pair_finder's kept candidates stay right when the filters change between
// frames; the filtered pairs are not handed to the method.
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using obbsat::collide_options;
using obbsat::method;
using obbsat::pair_filters;
using obbsat::pair_index;
using obbsat::rect_pose;

bool pair_less(const pair_index& x, const pair_index& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

bool same_pairs(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(), [](const pair_index& p, const pair_index& q) {
               return p.a == q.a && p.b == q.b;
           });
}

std::string difference(const std::vector<pair_index>& got, const std::vector<pair_index>& want) {
    std::vector<pair_index> extra, missing;
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra), pair_less);
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing), pair_less);
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

#define EXPECT_SAME_PAIRS(got, want) EXPECT_TRUE(same_pairs(got, want)) << difference(got, want)

collide_options options_for(method m, unsigned threads = 1) {
    collide_options o;
    o.test = m;
    o.threads = threads;
    return o;
}

std::vector<rect_pose> seeded_scene(std::size_t boxes, std::uint64_t seed, double pairs_per_box = 3.0) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.sizes = obbsat::scene_sizes::mixed;
    spec.seed = seed;
    spec.pairs_per_box = pairs_per_box;
    return obbsat::make_pose_scene(spec);
}

/// Filters of a set as the caller keeps them: which arrays are given is
/// chosen by the test (view()).
struct filter_arrays {
    std::vector<std::uint64_t> categories, masks;
    std::vector<std::int32_t> groups;
    bool with_categories = true, with_masks = true, with_groups = true;

    pair_filters view() const {
        pair_filters f;
        f.categories = with_categories ? categories.data() : nullptr;
        f.masks = with_masks ? masks.data() : nullptr;
        f.groups = with_groups ? groups.data() : nullptr;
        return f;
    }
    std::uint64_t category(std::size_t i) const { return with_categories ? categories[i] : ~std::uint64_t{0}; }
    std::uint64_t mask(std::size_t i) const { return with_masks ? masks[i] : ~std::uint64_t{0}; }
    std::int32_t group(std::size_t i) const { return with_groups ? groups[i] : 0; }
};

/// Random filters in the style of a game: four categories, masks that
/// leave out one or two of them now and then, and about half the boxes in
/// groups of up to four consecutive boxes (compound bodies; the scene's
/// neighbours in the plane are not its neighbours in the rows, so the
/// groups cut pairs all over).
filter_arrays random_filters(std::size_t count, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    filter_arrays f;
    f.categories.resize(count);
    f.masks.resize(count);
    f.groups.resize(count);
    std::int32_t group = 0;
    for (std::size_t i = 0; i < count; ++i) {
        f.categories[i] = std::uint64_t{1} << random.below(4);
        f.masks[i] = random.below(3) == 0 ? ~(std::uint64_t{1} << random.below(4)) & 0xf : ~std::uint64_t{0};
        if (i % 4 == 0) {
            group = random.below(2) == 0 ? 0 : static_cast<std::int32_t>(i / 4 + 1) * (random.below(2) == 0 ? 1 : -1);
        }
        f.groups[i] = group;
    }
    return f;
}

bool passes(const filter_arrays& x, std::size_t i, const filter_arrays& y, std::size_t j) {
    if ((x.category(i) & y.mask(j)) == 0 || (y.category(j) & x.mask(i)) == 0) {
        return false;
    }
    return !(x.group(i) != 0 && x.group(i) == y.group(j));
}

/// The pairs of `all` (one set's answer without filters) that the filters let through.
std::vector<pair_index> filtered(const std::vector<pair_index>& all, const filter_arrays& a, const filter_arrays& b) {
    std::vector<pair_index> out;
    for (const pair_index& p : all) {
        if (passes(a, p.a, b, p.b)) {
            out.push_back(p);
        }
    }
    return out;
}

std::vector<pair_index> streamed(obbsat::box_view boxes, const collide_options& options) {
    std::vector<pair_index> out;
    obbsat::find_pairs_each(boxes, options, [&](const pair_index* p, std::size_t n) { out.insert(out.end(), p, p + n); });
    std::sort(out.begin(), out.end(), pair_less);
    return out;
}

std::vector<pair_index> streamed(obbsat::box_view a, obbsat::box_view b, const collide_options& options) {
    std::vector<pair_index> out;
    obbsat::find_pairs_each(a, b, options, [&](const pair_index* p, std::size_t n) { out.insert(out.end(), p, p + n); });
    std::sort(out.begin(), out.end(), pair_less);
    return out;
}

/// Which arrays a case gives: all three, then each alone, then none.
const int given_cases[][3] = {{1, 1, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 0, 0}};

void give(filter_arrays& f, const int (&given)[3]) {
    f.with_categories = given[0] != 0;
    f.with_masks = given[1] != 0;
    f.with_groups = given[2] != 0;
}

std::string given_name(const int (&given)[3]) {
    return std::string(given[0] ? "categories " : "") + (given[1] ? "masks " : "") + (given[2] ? "groups" : "") +
           (given[0] + given[1] + given[2] == 0 ? "none" : "");
}

TEST(pair_filters, one_set_reports_the_unfiltered_pairs_the_rule_lets_through) {
    // 40000 boxes: two threads take two parts.
    const auto poses = seeded_scene(40000, 101);
    const obbsat::pose_records store(poses);
    filter_arrays f = random_filters(poses.size(), 102);
    for (const method m : {method::exact, method::local}) {
        for (const unsigned threads : {1u, 2u}) {
            const collide_options options = options_for(m, threads);
            const auto all = obbsat::find_pairs(store, options);
            for (const auto& given : given_cases) {
                give(f, given);
                const auto want = filtered(all, f, f);
                const obbsat::box_view view = obbsat::box_view(store).with_filters(f.view());
                const std::string what = std::string(obbsat::method_name(m)) + ", " + std::to_string(threads) +
                                         " threads, " + given_name(given);
                EXPECT_SAME_PAIRS(obbsat::find_pairs(view, options), want) << what;
                EXPECT_SAME_PAIRS(streamed(view, options), want) << what;
                // Rows in place, not a store: the same filters, the same pairs.
                EXPECT_SAME_PAIRS(obbsat::find_pairs(obbsat::box_view(poses).with_filters(f.view()), options), want)
                    << what;
            }
            give(f, given_cases[0]);
            EXPECT_LT(filtered(all, f, f).size(), all.size() * 9 / 10) << "the filters must drop many pairs";
        }
    }
}

TEST(pair_filters, corner_rows_are_filtered_as_poses_are) {
    const auto poses = seeded_scene(5000, 103);
    const obbsat::rect_records records = obbsat::corner_records_of(obbsat::pose_records(poses));
    const std::vector<obbsat::rect> corners(records.data(), records.data() + records.size());
    const filter_arrays f = random_filters(poses.size(), 104);
    for (const method m : {method::exact, method::sat4}) {
        const collide_options options = options_for(m);
        const auto want = filtered(obbsat::find_pairs(corners, options), f, f);
        EXPECT_SAME_PAIRS(obbsat::find_pairs(obbsat::box_view(corners).with_filters(f.view()), options), want)
            << obbsat::method_name(m);
        EXPECT_SAME_PAIRS(obbsat::find_pairs(obbsat::box_view(records).with_filters(f.view()), options), want)
            << obbsat::method_name(m);
    }
}

TEST(pair_filters, across_two_sets_each_side_has_its_own_filters) {
    const auto a = seeded_scene(30000, 105);
    const auto b = seeded_scene(20000, 106);
    filter_arrays fa = random_filters(a.size(), 107);
    filter_arrays fb = random_filters(b.size(), 108);
    // The groups of the two sides share numbers: a box of a and one of b in
    // group 5 are of one body, as two boxes of one set are.
    for (const method m : {method::exact, method::local}) {
        for (const unsigned threads : {1u, 2u}) {
            const collide_options options = options_for(m, threads);
            const auto all = obbsat::find_pairs(a, b, options);
            for (const auto& given_a : given_cases) {
                for (const std::size_t case_b : {0u, 5u, 3u}) {
                    const auto& given_b = given_cases[case_b];
                    give(fa, given_a);
                    give(fb, given_b);
                    const auto want = filtered(all, fa, fb);
                    const obbsat::box_view va = obbsat::box_view(a).with_filters(fa.view());
                    const obbsat::box_view vb = obbsat::box_view(b).with_filters(fb.view());
                    const std::string what = std::string(obbsat::method_name(m)) + ", " +
                                             std::to_string(threads) + " threads, a: " + given_name(given_a) +
                                             ", b: " + given_name(given_b);
                    EXPECT_SAME_PAIRS(obbsat::find_pairs(va, vb, options), want) << what;
                    EXPECT_SAME_PAIRS(streamed(va, vb, options), want) << what;
                }
            }
        }
    }
}

TEST(pair_filters, filtered_pairs_are_not_handed_to_the_method) {
    const auto poses = seeded_scene(20000, 109);
    const filter_arrays f = random_filters(poses.size(), 110);
    // A pair_finder's first call on a scene answers as find_pairs does, with its stats.
    obbsat::pair_finder plain(options_for(method::exact));
    obbsat::pair_finder with_filters(options_for(method::exact));
    const auto all = plain.find(poses);
    const auto some = with_filters.find(obbsat::box_view(poses).with_filters(f.view()));
    EXPECT_SAME_PAIRS(some, filtered(all, f, f));
    EXPECT_LT(some.size(), all.size());
    // The candidates that pass the filters, no more: fewer by at least the pairs dropped.
    EXPECT_LE(with_filters.stats().candidates + (all.size() - some.size()), plain.stats().candidates);
    EXPECT_GE(with_filters.stats().candidates, some.size());
}

TEST(pair_filters, a_crowd_of_two_bodies_pairs_only_across_them) {
    // Every box at one place: every pair is a candidate, and all those within
    // one body are dropped, block after block of the sweep.
    const std::size_t n = 3000;
    std::vector<rect_pose> boxes(n, rect_pose{{1.0f, 2.0f}, {1.0f, 0.5f}, {1.0f, 0.0f}});
    std::vector<std::int32_t> groups(n);
    for (std::size_t i = 0; i < n; ++i) {
        groups[i] = i % 3 == 0 ? 7 : -7;
    }
    pair_filters f;
    f.groups = groups.data();
    for (const unsigned threads : {1u, 2u}) {
        const auto got = obbsat::find_pairs(obbsat::box_view(boxes).with_filters(f), options_for(method::exact, threads));
        std::vector<pair_index> want;
        for (std::uint32_t i = 0; i < n; ++i) {
            for (std::uint32_t j = i + 1; j < n; ++j) {
                if (groups[i] != groups[j]) {
                    want.push_back(pair_index{i, j});
                }
            }
        }
        EXPECT_SAME_PAIRS(got, want) << threads << " threads";
    }
}

TEST(pair_filters, no_arrays_all_ones_and_zero_bits) {
    const auto poses = seeded_scene(4000, 111);
    const collide_options options = options_for(method::exact);
    const auto all = obbsat::find_pairs(poses, options);
    ASSERT_FALSE(all.empty());
    // The defaults, given or not.
    const obbsat::box_view plain(poses);
    EXPECT_FALSE(plain.filters().any());
    EXPECT_FALSE(plain.with_filters(pair_filters{}).filters().any());
    EXPECT_SAME_PAIRS(obbsat::find_pairs(plain.with_filters(pair_filters{}), options), all);
    std::vector<std::uint64_t> ones(poses.size(), ~std::uint64_t{0});
    std::vector<std::int32_t> zeros(poses.size(), 0);
    pair_filters defaults;
    defaults.categories = ones.data();
    defaults.masks = ones.data();
    defaults.groups = zeros.data();
    EXPECT_SAME_PAIRS(obbsat::find_pairs(plain.with_filters(defaults), options), all);
    // with_filters replaces the filters the view carried.
    std::vector<std::uint64_t> none(poses.size(), 0);
    pair_filters nothing;
    nothing.masks = none.data();
    EXPECT_TRUE(obbsat::find_pairs(plain.with_filters(nothing), options).empty());
    EXPECT_SAME_PAIRS(obbsat::find_pairs(plain.with_filters(nothing).with_filters(defaults), options), all);
    // One box that collides with nothing: its pairs go, the others stay.
    none.assign(poses.size(), ~std::uint64_t{0});
    none[all[0].a] = 0;
    std::vector<pair_index> want;
    for (const pair_index& p : all) {
        if (p.a != all[0].a && p.b != all[0].a) {
            want.push_back(p);
        }
    }
    EXPECT_SAME_PAIRS(obbsat::find_pairs(plain.with_filters(nothing), options), want);
    // An empty set and a single box with filters: nothing, as without.
    EXPECT_TRUE(obbsat::find_pairs(obbsat::box_view(poses.data(), 1).with_filters(defaults), options).empty());
    EXPECT_TRUE(obbsat::find_pairs(obbsat::box_view(poses.data(), 0).with_filters(defaults), poses, options).empty());
}

TEST(pair_filters, a_bad_row_is_still_refused_by_name) {
    auto poses = seeded_scene(100, 112);
    poses[17].half_extents.x = -1.0f;
    const filter_arrays f = random_filters(poses.size(), 113);
    try {
        obbsat::find_pairs(obbsat::box_view(poses).with_filters(f.view()), options_for(method::exact));
        FAIL() << "a negative half extent was taken";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("17"), std::string::npos) << e.what();
    }
}

/// The scene drifting a little each frame (a pair_finder then answers most
/// frames from its kept candidates).
std::vector<rect_pose> drifted(const std::vector<rect_pose>& start, int frame, std::uint64_t seed) {
    obbsat::seeded_random random(seed);
    std::vector<rect_pose> out = start;
    const float t = static_cast<float>(frame);
    for (rect_pose& p : out) {
        p.center.x += random.uniform(-0.01f, 0.01f) * t;
        p.center.y += random.uniform(-0.01f, 0.01f) * t;
    }
    return out;
}

/// Changes the filters in place (the same arrays, as a simulation would) at
/// some frames: a body split, categories flipped, masks dropped and given
/// back. Each change lets through pairs that the last filters dropped, so
/// kept candidates built with those would miss them.
void change_filters(filter_arrays& f, int frame, std::uint64_t seed) {
    obbsat::seeded_random random(seed + static_cast<std::uint64_t>(frame));
    switch (frame % 8) {
    case 3:
        for (std::size_t i = 0; i < f.groups.size(); i += 7) {
            f.groups[i] = 0;
        }
        break;
    case 5:
        for (std::size_t i = 0; i < f.categories.size(); i += 5) {
            f.categories[i] = std::uint64_t{1} << random.below(4);
        }
        break;
    case 6:
        f.with_masks = !f.with_masks;
        break;
    case 7:
        f.masks[random.below(f.masks.size())] = 0;
        f.groups[random.below(f.groups.size())] = 3;
        break;
    default:
        break;
    }
}

TEST(pair_filters, pair_finder_frames_equal_fresh_queries_as_the_filters_change) {
    const auto start = seeded_scene(40000, 114, 2.0);
    for (const method m : {method::exact, method::local}) {
        for (const unsigned threads : {1u, 2u}) {
            filter_arrays f = random_filters(start.size(), 115);
            obbsat::pair_finder finder(options_for(m, threads));
            std::size_t from_kept = 0, from_kept_after_change = 0;
            bool changed = false;
            for (int frame = 0; frame < 24; ++frame) {
                const auto poses = drifted(start, frame, 116);
                const obbsat::box_view view = obbsat::box_view(poses).with_filters(f.view());
                const auto got = finder.find(view);
                const auto want = filtered(obbsat::find_pairs(poses, options_for(m)), f, f);
                EXPECT_SAME_PAIRS(got, want) << obbsat::method_name(m) << ", " << threads << " threads, frame " << frame;
                from_kept += finder.stats().reused_candidates ? 1u : 0u;
                from_kept_after_change += changed && finder.stats().reused_candidates ? 1u : 0u;
                const std::vector<std::int32_t> groups_before = f.groups;
                const auto categories_before = f.categories;
                const bool masks_before = f.with_masks;
                change_filters(f, frame, 117);
                changed = groups_before != f.groups || categories_before != f.categories || masks_before != f.with_masks;
            }
            // Unchanged filters let the kept candidates serve; a change makes a full query.
            EXPECT_GE(from_kept, 8u) << obbsat::method_name(m) << ", " << threads << " threads";
            EXPECT_EQ(from_kept_after_change, 0u) << obbsat::method_name(m) << ", " << threads << " threads";
        }
    }
}

TEST(pair_finder_filters, filters_given_then_taken_away_across_two_sets) {
    const auto a_start = seeded_scene(30000, 118, 2.0);
    const auto b_start = seeded_scene(5000, 119, 2.0);
    filter_arrays fa = random_filters(a_start.size(), 120);
    filter_arrays fb = random_filters(b_start.size(), 121);
    for (const unsigned threads : {1u, 2u}) {
        obbsat::pair_finder finder(options_for(method::exact, threads));
        std::size_t from_kept = 0;
        for (int frame = 0; frame < 16; ++frame) {
            const auto a = drifted(a_start, frame, 122);
            const auto b = drifted(b_start, frame, 123);
            // Frames 0-3: both sides filtered; 4-7: a only; 8-11: none; 12-15: b only, its groups changed at 14.
            const bool filter_a = frame < 8;
            const bool filter_b = frame < 4 || frame >= 12;
            if (frame == 14) {
                std::fill(fb.groups.begin(), fb.groups.end(), 0);
            }
            obbsat::box_view va(a), vb(b);
            if (filter_a) {
                va = va.with_filters(fa.view());
            }
            if (filter_b) {
                vb = vb.with_filters(fb.view());
            }
            const auto all = obbsat::find_pairs(a, b, options_for(method::exact));
            filter_arrays none_a, none_b;
            give(none_a, given_cases[5]);
            give(none_b, given_cases[5]);
            const auto want = filtered(all, filter_a ? fa : none_a, filter_b ? fb : none_b);
            EXPECT_SAME_PAIRS(finder.find(va, vb), want) << threads << " threads, frame " << frame;
            from_kept += finder.stats().reused_candidates ? 1u : 0u;
        }
        EXPECT_GE(from_kept, 6u) << threads << " threads";
    }
}

}  // namespace
