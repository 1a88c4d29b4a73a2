// find_contacts against every pair of a small scene decided one by one: the
// pairs are exactly those the method calls colliding plus, with a margin,
// those whose contact has points; each contact is bit for bit contact_pairs'
// on that pair; poses, pose stores and corners; filters; a bad margin.
#include <obbsat/collide.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_records.hpp>

#include "scene/contact_scenes.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <thread>
#include <limits>
#include <vector>

namespace {

using obbsat::contact;
using obbsat::pair_index;
using contact_scenes::exact_on;
using contact_scenes::expect_same;
using contact_scenes::scene_of;

std::vector<obbsat::rect_pose> small_scene(std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.seed = seed;
    spec.boxes = 300;
    spec.sizes = obbsat::scene_sizes::mixed;
    spec.pairs_per_box = 3.0;
    return obbsat::make_pose_scene(spec);
}

/// What find_contacts must give, from every pair decided one by one.
template <class Store>
obbsat::scene_contacts expected_contacts(const Store& store, float margin) {
    return contact_scenes::contacts_decided_alone<obbsat::scene_contacts, obbsat::contact_options>(store, margin);
}

TEST(FindContacts, PosesMatchEveryPairDecidedAloneWithAndWithoutMargin) {
    const std::vector<obbsat::rect_pose> rows = small_scene(5);
    const obbsat::pose_records store(rows);
    for (const float margin : {0.0f, 0.05f, 0.5f}) {
        const obbsat::scene_contacts expected = expected_contacts(store, margin);
        ASSERT_FALSE(expected.pairs.empty());
        for (const obbsat::backend use : obbsat::runnable_backends()) {
            SCOPED_TRACE(obbsat::backend_name(use));
            expect_same(obbsat::find_contacts(rows, exact_on(use, 1), margin), expected);
            expect_same(obbsat::find_contacts(store, exact_on(use, 3), margin), expected);
        }
    }
}

TEST(FindContacts, AMarginAddsPairsThatDoNotCollide) {
    const obbsat::pose_records store(small_scene(8));
    const obbsat::scene_contacts touching = expected_contacts(store, 0.0f);
    const obbsat::scene_contacts near = expected_contacts(store, 0.5f);
    EXPECT_GT(near.pairs.size(), touching.pairs.size());
}

TEST(FindContacts, CornersMatchEveryPairDecidedAlone) {
    const obbsat::pose_records poses(small_scene(11));
    const obbsat::rect_records corners = obbsat::corner_records_of(poses);
    const std::vector<obbsat::rect> rows(corners.data(), corners.data() + corners.size());
    for (const float margin : {0.0f, 0.25f}) {
        const obbsat::scene_contacts expected = expected_contacts(corners, margin);
        expect_same(obbsat::find_contacts(corners, exact_on(obbsat::backend::automatic, 1), margin), expected);
        expect_same(obbsat::find_contacts(rows, exact_on(obbsat::backend::automatic, 2), margin), expected);
    }
}

TEST(FindContacts, PairFiltersApplyToPairsWithinTheMargin) {
    // Three squares 0.1 apart in a row: with a margin of 0.2 the pairs (0, 1)
    // and (1, 2) are near; boxes 0 and 1 in one group never pair.
    const std::vector<obbsat::rect_pose> rows = {
        {{0, 0}, {1, 1}, {1, 0}}, {{2.1f, 0}, {1, 1}, {1, 0}}, {{4.2f, 0}, {1, 1}, {1, 0}}};
    const obbsat::scene_contacts all = obbsat::find_contacts(rows, exact_on(obbsat::backend::automatic, 1), 0.2f);
    ASSERT_EQ(all.pairs.size(), 2u);
    const std::int32_t groups[] = {7, 7, 0};
    obbsat::pair_filters filters;
    filters.groups = groups;
    const obbsat::scene_contacts filtered = obbsat::find_contacts(
        obbsat::box_view(rows).with_filters(filters), exact_on(obbsat::backend::automatic, 1), 0.2f);
    ASSERT_EQ(filtered.pairs.size(), 1u);
    EXPECT_EQ(filtered.pairs[0].a, 1u);
    EXPECT_EQ(filtered.pairs[0].b, 2u);
    EXPECT_EQ(filtered.contacts[0].point_count, 2u);
}

TEST(FindContacts, RefusesABadMarginAndABadBox) {
    const std::vector<obbsat::rect_pose> rows = {{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1, 0}}};
    const auto options = exact_on(obbsat::backend::automatic, 1);
    EXPECT_THROW(obbsat::find_contacts(rows, options, -1.0f), obbsat::invalid_input);
    EXPECT_THROW(obbsat::find_contacts(rows, options, std::numeric_limits<float>::quiet_NaN()),
                 obbsat::invalid_input);
    EXPECT_THROW(obbsat::find_contacts(rows, options, std::numeric_limits<float>::infinity()),
                 obbsat::invalid_input);
    std::vector<obbsat::rect_pose> bad = rows;
    bad[1].half_extents.y = -1;
    try {
        obbsat::find_contacts(bad, options, 0.5f);
        FAIL() << "a negative half extent was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pose 1"), std::string::npos) << e.what();
    }
}

/// The contacts find_contacts must give at margin 0: find_pairs' pairs, each
/// with contact_pairs' contact on the scalar backend (the reference's bits).
template <class Store>
obbsat::scene_contacts contacts_of_found_pairs(const Store& store, const obbsat::collide_options& options) {
    obbsat::scene_contacts expected;
    expected.pairs = obbsat::find_pairs(store, options);
    obbsat::contact_options scalar;
    scalar.use = obbsat::backend::scalar;
    expected.contacts = obbsat::contact_pairs(store, expected.pairs, scalar);
    return expected;
}


// Enough boxes for several threads' shares and several units each, and
// enough pairs that each unit fills more than one block of contacts.
constexpr std::size_t many_boxes = 40000;

TEST(FindContacts, EqualsContactPairsOverFindPairsOnEveryBackendThreadCountAndMethod) {
    const std::vector<obbsat::rect_pose> rows = scene_of(many_boxes, 21);
    const obbsat::pose_records store(rows);
    const obbsat::rect_records corners = obbsat::corner_records_of(store);
    for (const obbsat::method test : {obbsat::method::exact, obbsat::method::local, obbsat::method::conservative}) {
        obbsat::collide_options options;
        options.test = test;
        const obbsat::scene_contacts on_poses = contacts_of_found_pairs(store, options);
        ASSERT_GT(on_poses.pairs.size(), many_boxes);
        for (const obbsat::backend use : obbsat::runnable_backends()) {
            for (const unsigned threads : {1u, 2u, 3u, 0u}) {
                SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + obbsat::method_name(test) + ", " +
                             std::to_string(threads) + " threads");
                options.use = use;
                options.threads = threads;
                expect_same(obbsat::find_contacts(rows, options), on_poses);   // pose rows, read in place
                expect_same(obbsat::find_contacts(store, options), on_poses);  // a pose store's records
            }
        }
    }
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    const obbsat::scene_contacts on_corners = contacts_of_found_pairs(corners, options);
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 3u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", corners, " + std::to_string(threads) + " threads");
            options.use = use;
            options.threads = threads;
            expect_same(obbsat::find_contacts(corners, options), on_corners);
        }
    }
}

TEST(FindContacts, WithAMarginTheSameOnEveryBackendAndThreadCount) {
    // The small scenes above check the pairs against every pair decided
    // alone; here a larger one checks that every backend and thread count
    // gives those same pairs, each with contact_pairs' contact at the margin.
    const std::vector<obbsat::rect_pose> rows = scene_of(many_boxes, 22);
    const obbsat::pose_records store(rows);
    const obbsat::rect_records corners = obbsat::corner_records_of(store);
    constexpr float margin = 0.05f;
    obbsat::contact_options scalar;
    scalar.use = obbsat::backend::scalar;
    scalar.margin = margin;
    const obbsat::scene_contacts first = obbsat::find_contacts(store, exact_on(obbsat::backend::scalar, 1), margin);
    const std::vector<pair_index> colliding = obbsat::find_pairs(store, exact_on(obbsat::backend::scalar, 1));
    ASSERT_GT(first.pairs.size(), colliding.size());
    const obbsat::scene_contacts expected{first.pairs, obbsat::contact_pairs(store, first.pairs, scalar)};
    const obbsat::scene_contacts expected_corners{first.pairs, obbsat::contact_pairs(corners, first.pairs, scalar)};
    for (const obbsat::backend use : obbsat::runnable_backends()) {
        for (const unsigned threads : {1u, 2u, 3u}) {
            SCOPED_TRACE(std::string(obbsat::backend_name(use)) + ", " + std::to_string(threads) + " threads");
            expect_same(obbsat::find_contacts(rows, exact_on(use, threads), margin), expected);
            expect_same(obbsat::find_contacts(store, exact_on(use, threads), margin), expected);
            expect_same(obbsat::find_contacts(corners, exact_on(use, threads), margin), expected_corners);
        }
    }
}

TEST(FindContacts, IntoAKeptAnswerLargerOrSmallerOnEveryThreadCount) {
    // An answer kept from call to call, in turn larger and smaller than the
    // next: its old contacts are overwritten in place and only those past
    // them are new (appended by one thread, written in place by several).
    const obbsat::pose_records large(scene_of(60000, 23));
    const obbsat::pose_records small(scene_of(2000, 24));
    for (const unsigned threads : {1u, 2u, 3u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const auto options = exact_on(obbsat::backend::automatic, threads);
        const obbsat::scene_contacts want_large = contacts_of_found_pairs(large, options);
        const obbsat::scene_contacts want_small = contacts_of_found_pairs(small, options);
        ASSERT_GT(want_large.pairs.size(), 2 * want_small.pairs.size());
        obbsat::scene_contacts found;
        found.contacts.resize(10);  // a few contacts before the first answer: overwritten, never kept
        found.pairs.resize(10);
        obbsat::find_contacts(small, options, 0.0f, found);
        expect_same(found, want_small);
        obbsat::find_contacts(large, options, 0.0f, found);
        expect_same(found, want_large);
        // Memory enough: the next answers take no fresh memory.
        const pair_index* const pairs_memory = found.pairs.data();
        const contact* const contacts_memory = found.contacts.data();
        obbsat::find_contacts(small, options, 0.0f, found);
        expect_same(found, want_small);
        obbsat::find_contacts(large, options, 0.0f, found);
        expect_same(found, want_large);
        EXPECT_EQ(found.pairs.data(), pairs_memory);
        EXPECT_EQ(found.contacts.data(), contacts_memory);
        // With a margin, into the same kept answer.
        const obbsat::scene_contacts near_large = obbsat::find_contacts(large, options, 0.05f);
        const obbsat::scene_contacts near_small = obbsat::find_contacts(small, options, 0.05f);
        ASSERT_GT(near_large.pairs.size(), want_large.pairs.size());
        obbsat::find_contacts(small, options, 0.05f, found);
        expect_same(found, near_small);
        obbsat::find_contacts(large, options, 0.05f, found);
        expect_same(found, near_large);
    }
}

TEST(FindContacts, ARefusedCallLeavesAKeptAnswerAsItWas) {
    // The query refuses the box; the answer of the call before stays whole.
    const obbsat::pose_records store(scene_of(3000, 27));
    std::vector<obbsat::rect_pose> bad = scene_of(3000, 28);
    bad[1234].half_extents.x = std::numeric_limits<float>::infinity();
    const auto options = exact_on(obbsat::backend::automatic, 2);
    for (const float margin : {0.0f, 0.05f}) {
        SCOPED_TRACE("margin " + std::to_string(margin));
        obbsat::scene_contacts found;
        obbsat::find_contacts(store, options, margin, found);
        const obbsat::scene_contacts before = found;
        ASSERT_FALSE(before.pairs.empty());
        try {
            obbsat::find_contacts(bad, options, margin, found);
            FAIL() << "an infinite half extent was accepted";
        } catch (const obbsat::invalid_input& e) {
            EXPECT_NE(std::string(e.what()).find("1234"), std::string::npos) << e.what();
        }
        expect_same(found, before);
    }
}

TEST(FindContacts, CallsFromSeveralThreadsAtOnceEachGetTheirOwn) {
    // With a margin one call holds the kept memory; the others make their own meanwhile.
    const obbsat::pose_records first(scene_of(20000, 25));
    const obbsat::pose_records second(scene_of(30000, 26));
    const auto options = exact_on(obbsat::backend::automatic, 1);
    for (const float margin : {0.0f, 0.05f}) {
        SCOPED_TRACE("margin " + std::to_string(margin));
        const obbsat::scene_contacts want_first = obbsat::find_contacts(first, options, margin);
        const obbsat::scene_contacts want_second = obbsat::find_contacts(second, options, margin);
        if (margin == 0.0f) {
            expect_same(want_first, contacts_of_found_pairs(first, options));
            expect_same(want_second, contacts_of_found_pairs(second, options));
        }
        std::vector<obbsat::scene_contacts> got(8);
        std::vector<std::thread> callers;
        for (std::size_t t = 0; t < got.size(); ++t) {
            callers.emplace_back(
                [&, t] { got[t] = obbsat::find_contacts(t % 2 == 0 ? first : second, options, margin); });
        }
        for (std::thread& caller : callers) {
            caller.join();
        }
        for (std::size_t t = 0; t < got.size(); ++t) {
            SCOPED_TRACE("caller " + std::to_string(t));
            expect_same(got[t], t % 2 == 0 ? want_first : want_second);
        }
    }
}

TEST(FindContacts, RefusesDoubleRowsAndRowsContactsDoNotAccept) {
    const auto options = exact_on(obbsat::backend::automatic, 1);
    const std::vector<obbsat::rect_pose64> doubles = {{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1, 0}}};
    EXPECT_THROW(obbsat::find_contacts(doubles, options), obbsat::invalid_input);
    // A rotation of length 1e-30 is a valid pose, but its square is not a normal float.
    std::vector<obbsat::rect_pose> rows = {{{0, 0}, {1, 1}, {1, 0}}, {{1, 0}, {1, 1}, {1e-30f, 0}}};
    try {
        obbsat::find_contacts(rows, options);
        FAIL() << "a rotation too short for contacts was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pose 1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("too short or too long"), std::string::npos) << e.what();
    }
    // A row that is no box at all is refused as such, though an earlier one is not accepted.
    rows.push_back({{2, 0}, {-1, 1}, {1, 0}});
    try {
        obbsat::find_contacts(rows, options);
        FAIL() << "a negative half extent was accepted";
    } catch (const obbsat::invalid_input& e) {
        EXPECT_NE(std::string(e.what()).find("pose 2"), std::string::npos) << e.what();
    }
}

}  // namespace
