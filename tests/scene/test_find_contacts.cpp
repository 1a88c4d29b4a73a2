// find_contacts against every pair of a small scene decided one by one: the
// pairs are exactly those the method calls colliding plus, with a margin,
// those whose contact has points; each contact is bit for bit contact_pairs'
// on that pair; poses, pose stores and corners; filters; a bad margin.
#include <obbsat/collide.hpp>
#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/pose_conversion.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>
#include <obbsat/rect_records.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <limits>
#include <vector>

namespace {

using obbsat::contact;
using obbsat::pair_index;

std::vector<obbsat::rect_pose> small_scene(std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.seed = seed;
    spec.boxes = 300;
    spec.sizes = obbsat::scene_sizes::mixed;
    spec.pairs_per_box = 3.0;
    return obbsat::make_pose_scene(spec);
}

/// Every pair i < j of `store`.
template <class Store>
std::vector<pair_index> all_pairs(const Store& store) {
    std::vector<pair_index> pairs;
    for (std::uint32_t i = 0; i < store.size(); ++i) {
        for (std::uint32_t j = i + 1; j < store.size(); ++j) {
            pairs.push_back({i, j});
        }
    }
    return pairs;
}

/// What find_contacts must give, from every pair decided one by one.
template <class Store>
obbsat::scene_contacts expected_contacts(const Store& store, float margin) {
    const std::vector<pair_index> pairs = all_pairs(store);
    std::vector<std::uint8_t> verdicts(pairs.size());
    obbsat::collide_options exact;
    exact.test = obbsat::method::exact;
    obbsat::collide_pairs(store, pairs.data(), pairs.size(), verdicts.data(), exact);
    obbsat::contact_options options;
    options.margin = margin;
    options.use = obbsat::backend::scalar;
    const std::vector<contact> contacts = obbsat::contact_pairs(store, pairs, options);
    obbsat::scene_contacts expected;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (verdicts[k] || (margin > 0 && contacts[k].point_count > 0)) {
            expected.pairs.push_back(pairs[k]);
            expected.contacts.push_back(contacts[k]);
        }
    }
    return expected;
}

void expect_same(const obbsat::scene_contacts& found, const obbsat::scene_contacts& expected) {
    ASSERT_EQ(found.pairs.size(), expected.pairs.size());
    ASSERT_EQ(found.contacts.size(), expected.contacts.size());
    for (std::size_t k = 0; k < found.pairs.size(); ++k) {
        ASSERT_EQ(found.pairs[k].a, expected.pairs[k].a) << "row " << k;
        ASSERT_EQ(found.pairs[k].b, expected.pairs[k].b) << "row " << k;
        EXPECT_EQ(std::memcmp(&found.contacts[k], &expected.contacts[k], sizeof(contact)), 0)
            << "pair " << found.pairs[k].a << "," << found.pairs[k].b;
    }
}

obbsat::collide_options exact_on(obbsat::backend use, unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.use = use;
    options.threads = threads;
    return options;
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

}  // namespace
