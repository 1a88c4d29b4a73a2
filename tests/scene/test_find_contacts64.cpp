// find_contacts64 (find_contacts on double rows) against every pair of a
// small double scene decided one by one: the pairs are exactly those the
// double method calls colliding plus, with a margin, those whose double
// contact has points; each contact is bit for bit contact_pairs' over the
// double store. Double poses read in place (six doubles a row, copied into
// records for the kernels), double stores and double corners; far from the
// origin (UTM-like coordinates, where float32 would decide otherwise); every
// backend, thread count and double method; a kept answer; the refusals.
#include <obbsat/collide.hpp>
#include <obbsat/collide64.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records64.hpp>

#include "scene/contact_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using obbsat::contact64;
using obbsat::pair_index;
using obbsat::rect64;
using obbsat::rect_pose64;
using contact_scenes::exact_on;
using contact_scenes::expect_same;

using contact_scenes::double_scene_of;
using contact_scenes::far_x;
using contact_scenes::far_y;

/// The corners UL, UR, LR, LL of a double pose, computed in double.
rect64 corners_of(const rect_pose64& p) {
    const double ux = p.rotation.x * p.half_extents.x, uy = p.rotation.y * p.half_extents.x;
    const double vx = -p.rotation.y * p.half_extents.y, vy = p.rotation.x * p.half_extents.y;
    const double cx = p.center.x, cy = p.center.y;
    return rect64{{cx - ux + vx, cy - uy + vy}, {cx + ux + vx, cy + uy + vy}, {cx + ux - vx, cy + uy - vy},
                  {cx - ux - vx, cy - uy - vy}};
}

std::vector<rect64> corners_of(const std::vector<rect_pose64>& poses) {
    std::vector<rect64> out;
    for (const rect_pose64& p : poses) {
        out.push_back(corners_of(p));
    }
    return out;
}

/// What find_contacts64 must give, from every pair decided one by one in double.
template <class Store>
obbsat::scene_contacts64 expected_contacts(const Store& store, double margin) {
    return contact_scenes::contacts_decided_alone<obbsat::scene_contacts64, obbsat::contact_options64>(store,
                                                                                                      margin);
}

/// The contacts find_contacts64 must give at margin 0: find_pairs' pairs on
/// the double rows, each with contact_pairs' double contact on the scalar
/// backend (the double reference's bits).
template <class Store>
obbsat::scene_contacts64 contacts_of_found_pairs(const Store& store, const obbsat::collide_options& options,
                                                 double margin = 0.0) {
    obbsat::scene_contacts64 expected;
    expected.pairs = obbsat::find_pairs(store, options);
    obbsat::contact_options64 scalar;
    scalar.use = obbsat::backend::scalar;
    scalar.margin = margin;
    expected.contacts = obbsat::contact_pairs(store, expected.pairs, scalar);
    return expected;
}

TEST(FindContacts64, PosesMatchEveryPairDecidedAloneNearAndFarFromTheOrigin) {
    for (const double dx : {0.0, far_x}) {
        const std::vector<rect_pose64> rows = double_scene_of(300, 5, dx, dx == 0.0 ? 0.0 : far_y);
        const obbsat::pose_records64 store(rows);
        for (const double margin : {0.0, 0.05, 0.5}) {
            SCOPED_TRACE("at x " + std::to_string(dx) + ", margin " + std::to_string(margin));
            const obbsat::scene_contacts64 expected = expected_contacts(store, margin);
            ASSERT_FALSE(expected.pairs.empty());
            for (const obbsat::backend use : obbsat::runnable_backends()) {
                SCOPED_TRACE(obbsat::backend_name(use));
                expect_same(obbsat::find_contacts64(rows, exact_on(use, 1), margin), expected);
                expect_same(obbsat::find_contacts64(store, exact_on(use, 3), margin), expected);
            }
        }
    }
}

TEST(FindContacts64, CornersMatchEveryPairDecidedAlone) {
    const std::vector<rect64> rows = corners_of(double_scene_of(300, 11, far_x, far_y));
    const obbsat::rect_records64 store(rows);
    for (const double margin : {0.0, 0.25}) {
        SCOPED_TRACE("margin " + std::to_string(margin));
        const obbsat::scene_contacts64 expected = expected_contacts(store, margin);
        ASSERT_FALSE(expected.pairs.empty());
        for (const obbsat::backend use : obbsat::runnable_backends()) {
            SCOPED_TRACE(obbsat::backend_name(use));
            expect_same(obbsat::find_contacts64(store, exact_on(use, 1), margin), expected);
            expect_same(obbsat::find_contacts64(rows, exact_on(use, 2), margin), expected);
        }
    }
}

TEST(FindContacts64, FarFromTheOriginDoublesDecideWhatFloatsWouldNot) {
    // Two unit squares 0.001 apart at UTM-like x: rounded to float32 (steps of
    // 0.03125 there) their centers are exactly 2 apart, so the floats touch;
    // the doubles are apart, have no contact at margin 0, and one point each
    // side within a margin of 0.002.
    const std::vector<rect_pose64> rows = {{{far_x - 0.025, far_y}, {1, 1}, {1, 0}},
                                           {{far_x + 1.976, far_y}, {1, 1}, {1, 0}}};
    std::vector<obbsat::rect_pose> rounded;
    for (const rect_pose64& p : rows) {
        rounded.push_back({{static_cast<float>(p.center.x), static_cast<float>(p.center.y)}, {1, 1}, {1, 0}});
    }
    const auto options = exact_on(obbsat::backend::automatic, 1);
    ASSERT_EQ(obbsat::find_contacts(rounded, options).pairs.size(), 1u) << "the floats should touch";
    EXPECT_TRUE(obbsat::find_contacts64(rows, options).pairs.empty());
    const obbsat::scene_contacts64 near = obbsat::find_contacts64(rows, options, 0.002);
    ASSERT_EQ(near.pairs.size(), 1u);
    EXPECT_EQ(near.contacts[0].point_count, 2u);
    EXPECT_LT(near.contacts[0].depth, 0.0);
    EXPECT_GT(near.contacts[0].depth, -0.0011);
    EXPECT_TRUE(obbsat::find_contacts64(rows, options, 0.0009).pairs.empty());
}

// Enough boxes for several threads' shares and several units each, and
// enough pairs that each unit fills more than one block of contacts.
constexpr std::size_t many_boxes = 40000;

TEST(FindContacts64, EqualsContactPairsOverFindPairsOnEveryBackendThreadCountAndMethod) {
    const std::vector<rect_pose64> rows = double_scene_of(many_boxes, 21, far_x, far_y);
    const obbsat::pose_records64 store(rows);
    const std::vector<rect64> corner_rows = corners_of(rows);
    const obbsat::rect_records64 corners(corner_rows);
    for (const obbsat::method test : obbsat::methods_on_doubles(obbsat::store_kind::poses)) {
        obbsat::collide_options options;
        options.test = test;
        const obbsat::scene_contacts64 on_poses = contacts_of_found_pairs(store, options);
        ASSERT_GT(on_poses.pairs.size(), many_boxes);
        for (const obbsat::backend use : obbsat::runnable_backends()) {
            for (const unsigned threads : {1u, 2u, 3u, 0u}) {
                SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + obbsat::method_name(test) + ", " +
                             std::to_string(threads) + " threads");
                options.use = use;
                options.threads = threads;
                expect_same(obbsat::find_contacts64(rows, options), on_poses);   // pose rows, six doubles each
                expect_same(obbsat::find_contacts64(store, options), on_poses);  // a double store's records
            }
        }
    }
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    const obbsat::scene_contacts64 on_corners = contacts_of_found_pairs(corners, options);
    ASSERT_GT(on_corners.pairs.size(), many_boxes);
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 3u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", corners, " + std::to_string(threads) + " threads");
            options.use = use;
            options.threads = threads;
            expect_same(obbsat::find_contacts64(corners, options), on_corners);
            expect_same(obbsat::find_contacts64(corner_rows, options), on_corners);
        }
    }
}

TEST(FindContacts64, WithAMarginTheSameOnEveryBackendAndThreadCount) {
    // The small scenes above check the pairs against every pair decided
    // alone; here a larger one checks that every backend and thread count
    // gives those same pairs, each with contact_pairs' contact at the margin.
    const std::vector<rect_pose64> rows = double_scene_of(many_boxes, 22, far_x, far_y);
    const obbsat::pose_records64 store(rows);
    constexpr double margin = 0.05;
    const obbsat::scene_contacts64 first =
        obbsat::find_contacts64(store, exact_on(obbsat::backend::scalar, 1), margin);
    const std::vector<pair_index> colliding = obbsat::find_pairs(store, exact_on(obbsat::backend::scalar, 1));
    ASSERT_GT(first.pairs.size(), colliding.size());
    obbsat::contact_options64 scalar;
    scalar.use = obbsat::backend::scalar;
    scalar.margin = margin;
    const obbsat::scene_contacts64 expected{first.pairs, obbsat::contact_pairs(store, first.pairs, scalar)};
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 2u, 3u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + std::to_string(threads) + " threads");
            expect_same(obbsat::find_contacts64(rows, exact_on(use, threads), margin), expected);
            expect_same(obbsat::find_contacts64(store, exact_on(use, threads), margin), expected);
        }
    }
}

TEST(FindContacts64, PairFiltersApplyToPairsWithinTheMargin) {
    // Three squares 0.1 apart in a row far from the origin: with a margin of
    // 0.2 the pairs (0, 1) and (1, 2) are near; boxes 0 and 1 in one group never pair.
    const std::vector<rect_pose64> rows = {{{far_x, far_y}, {1, 1}, {1, 0}},
                                           {{far_x + 2.1, far_y}, {1, 1}, {1, 0}},
                                           {{far_x + 4.2, far_y}, {1, 1}, {1, 0}}};
    const auto options = exact_on(obbsat::backend::automatic, 1);
    ASSERT_EQ(obbsat::find_contacts64(rows, options, 0.2).pairs.size(), 2u);
    const std::int32_t groups[] = {7, 7, 0};
    obbsat::pair_filters filters;
    filters.groups = groups;
    const obbsat::scene_contacts64 filtered =
        obbsat::find_contacts64(obbsat::box_view(rows).with_filters(filters), options, 0.2);
    ASSERT_EQ(filtered.pairs.size(), 1u);
    EXPECT_EQ(filtered.pairs[0].a, 1u);
    EXPECT_EQ(filtered.pairs[0].b, 2u);
    EXPECT_EQ(filtered.contacts[0].point_count, 2u);
}

TEST(FindContacts64, IntoAKeptAnswerLargerOrSmallerAndARefusedCallLeavesItAsItWas) {
    const std::vector<rect_pose64> large = double_scene_of(30000, 23, far_x, far_y);
    const std::vector<rect_pose64> small = double_scene_of(2000, 24, far_x, far_y);
    for (const unsigned threads : {1u, 2u}) {
        for (const double margin : {0.0, 0.05}) {
            SCOPED_TRACE(std::to_string(threads) + " threads, margin " + std::to_string(margin));
            const auto options = exact_on(obbsat::backend::automatic, threads);
            const obbsat::scene_contacts64 want_large = obbsat::find_contacts64(large, options, margin);
            const obbsat::scene_contacts64 want_small = obbsat::find_contacts64(small, options, margin);
            ASSERT_GT(want_large.pairs.size(), 2 * want_small.pairs.size());
            if (margin == 0.0) {
                expect_same(want_large, contacts_of_found_pairs(obbsat::pose_records64(large), options));
            }
            obbsat::scene_contacts64 found;
            found.pairs.resize(10);  // a few elements before the first answer: overwritten, never kept
            found.contacts.resize(10);
            for (int round = 0; round < 2; ++round) {
                obbsat::find_contacts(small, options, margin, found);
                expect_same(found, want_small);
                obbsat::find_contacts(large, options, margin, found);
                expect_same(found, want_large);
            }
            std::vector<rect_pose64> bad = small;
            bad[1234].center.y = std::numeric_limits<double>::quiet_NaN();
            try {
                obbsat::find_contacts(bad, options, margin, found);
                FAIL() << "a NaN center was accepted";
            } catch (const obbsat::invalid_input& e) {
                EXPECT_NE(std::string(e.what()).find("pose 1234"), std::string::npos) << e.what();
            }
            expect_same(found, want_large);
        }
    }
}

/// The message of the invalid_input `call` throws, or "" when it throws none.
template <class Call>
std::string refusal_of(const Call& call) {
    try {
        call();
    } catch (const obbsat::invalid_input& e) {
        return e.what();
    }
    return "";
}

TEST(FindContacts64, ARotationContactsRefuseIsNamedWhicheverThreadCopiesItsRow) {
    // rect_pose64 rows are checked as each thread copies its share into
    // records, after the query: the refused row is named on any thread
    // count, and a row that is no box at all, later in the rows, is still
    // refused first.
    const std::vector<rect_pose64> rows = double_scene_of(40000, 25, far_x, far_y);
    for (const unsigned threads : {1u, 2u, 3u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const auto options = exact_on(obbsat::backend::automatic, threads);
        for (const std::size_t row : {std::size_t{7}, std::size_t{20000}, std::size_t{39999}}) {
            std::vector<rect_pose64> bad = rows;
            bad[row].rotation = {1e-200, 0.0};
            const std::string message = refusal_of([&] { obbsat::find_contacts64(bad, options); });
            EXPECT_NE(message.find("pose " + std::to_string(row) + ":"), std::string::npos) << message;
            EXPECT_NE(message.find("normal double"), std::string::npos) << message;
            // Refused once the query has run: a kept answer is as it was.
            const obbsat::scene_contacts64 want = obbsat::find_contacts64(rows, options);
            obbsat::scene_contacts64 kept = want;
            for (const double margin : {0.0, 0.05}) {
                EXPECT_NE(refusal_of([&] { obbsat::find_contacts(bad, options, margin, kept); }), "");
                expect_same(kept, want);
            }
        }
        std::vector<rect_pose64> bad = rows;
        bad[100].rotation = {1e-200, 0.0};
        bad[30000].center.x = std::numeric_limits<double>::quiet_NaN();
        const std::string message = refusal_of([&] { obbsat::find_contacts64(bad, options); });
        EXPECT_NE(message.find("pose 30000"), std::string::npos) << message;
    }
}

TEST(FindContacts64, RefusesFloatRowsBadMarginsBadRowsAndMethods) {
    const std::vector<rect_pose64> rows = {{{far_x, far_y}, {1, 1}, {1, 0}}, {{far_x + 1, far_y}, {1, 1}, {1, 0}}};
    const auto options = exact_on(obbsat::backend::automatic, 1);
    // Each precision's call takes its own rows only: no contact is rounded.
    const std::vector<obbsat::rect_pose> floats = {{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1, 0}}};
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts64(floats, options); }).find("float"), std::string::npos);
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts(rows, options); }).find("find_contacts64"), std::string::npos);
    obbsat::scene_contacts64 found;
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts(floats, options, 0.0, found); }), "");
    for (const double margin : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        EXPECT_NE(refusal_of([&] { obbsat::find_contacts64(rows, options, margin); }).find("margin"),
                  std::string::npos);
    }
    // A row that is no box, named with its field.
    std::vector<rect_pose64> bad = rows;
    bad[1].half_extents.x = std::numeric_limits<double>::infinity();
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts64(bad, options, 0.5); }).find("pose 1"), std::string::npos);
    std::vector<rect64> bad_corners = corners_of(rows);
    bad_corners[0].lr.y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts64(bad_corners, options); }).find("rectangle 0"),
              std::string::npos);
    // A valid pose whose c*c + s*s is not a normal double, and a quad that is not convex.
    bad = rows;
    bad[1].rotation = {1e-200, 0.0};
    const std::string short_rotation = refusal_of([&] { obbsat::find_contacts64(bad, options); });
    EXPECT_NE(short_rotation.find("pose 1"), std::string::npos) << short_rotation;
    EXPECT_NE(short_rotation.find("normal double"), std::string::npos) << short_rotation;
    bad_corners = corners_of(rows);
    std::swap(bad_corners[1].ul, bad_corners[1].ur);  // self-intersecting
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts64(bad_corners, options); }).find("rectangle 1"),
              std::string::npos);
    // A method that does not run on double poses.
    obbsat::collide_options sat4 = options;
    sat4.test = obbsat::method::sat4;
    EXPECT_NE(refusal_of([&] { obbsat::find_contacts64(rows, sat4); }).find("does not run on double"),
              std::string::npos);
}

}  // namespace
