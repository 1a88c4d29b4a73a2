// The one-shot scene queries' working memory kept between calls
// (kernel/scene/spare_search.hpp, obbsat::release_scratch): it is kept after
// a query and freed by release_scratch, and a query in borrowed memory
// answers as one in fresh memory, whatever ran before it, whatever runs
// beside it; the same for the double queries and find_contacts64's records
// (kernel/scene/query_contacts.hpp).
#include "scene/query_contacts.hpp"
#include "scene/spare_search.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/find_contacts.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pose_scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

using obbsat::pair_index;
using obbsat::rect_pose;
using obbsat::rect_pose64;

std::vector<rect_pose> scene_of(std::size_t boxes, obbsat::scene_sizes sizes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.sizes = sizes;
    spec.seed = seed;
    spec.pairs_per_box = 3.0;
    return obbsat::make_pose_scene(spec);
}

obbsat::collide_options options_of(unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::exact;
    options.threads = threads;
    return options;
}

bool same(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return std::equal(x.begin(), x.end(), y.begin(), y.end(),
                      [](const pair_index& p, const pair_index& q) { return p.a == q.a && p.b == q.b; });
}

/// The answer of a query that finds no memory kept.
std::vector<pair_index> fresh_answer(obbsat::box_view boxes, const obbsat::collide_options& options) {
    obbsat::release_scratch();
    return obbsat::find_pairs(boxes, options);
}

TEST(SpareSearch, KeptAfterAQueryAndFreedByReleaseScratch) {
    const std::vector<rect_pose> boxes = scene_of(20000, obbsat::scene_sizes::uniform, 3);
    obbsat::release_scratch();
    EXPECT_EQ(obbsat::detail::spare_search_bytes(), 0u);
    const std::vector<pair_index> pairs = obbsat::find_pairs(boxes, options_of(1));
    ASSERT_FALSE(pairs.empty());
    // At least the records in the query's order (32 bytes a box) and its order.
    EXPECT_GE(obbsat::detail::spare_search_bytes(), 36u * boxes.size());
    obbsat::release_scratch();
    EXPECT_EQ(obbsat::detail::spare_search_bytes(), 0u);
}

TEST(SpareSearch, StreamingQueriesKeepTheirMemoryToo) {
    const std::vector<rect_pose> boxes = scene_of(20000, obbsat::scene_sizes::mixed, 4);
    obbsat::release_scratch();
    std::size_t streamed = 0;
    obbsat::find_pairs_each(boxes, options_of(2), [&](const pair_index*, std::size_t count) { streamed += count; });
    EXPECT_GT(streamed, 0u);
    EXPECT_GE(obbsat::detail::spare_search_bytes(), 36u * boxes.size());
    obbsat::release_scratch();
}

TEST(SpareSearch, BorrowedMemoryAnswersAsFreshMemory) {
    // Scenes of other sizes and kinds one after the other, each query
    // borrowing the last one's memory: larger buffers, a last order and
    // strips of another scene in them, the pairs of another query.
    const std::vector<rect_pose> large = scene_of(30000, obbsat::scene_sizes::mixed, 5);
    const std::vector<rect_pose> small = scene_of(3000, obbsat::scene_sizes::uniform, 6);
    const std::vector<rect_pose> other = scene_of(30000, obbsat::scene_sizes::uniform, 7);
    const std::vector<rect_pose> b_side(other.begin(), other.begin() + 5000);
    for (const unsigned threads : {1u, 2u}) {
        const obbsat::collide_options options = options_of(threads);
        const std::vector<pair_index> want_large = fresh_answer(large, options);
        const std::vector<pair_index> want_small = fresh_answer(small, options);
        const std::vector<pair_index> want_other = fresh_answer(other, options);
        obbsat::release_scratch();
        const std::vector<pair_index> want_cross = obbsat::find_pairs(small, b_side, options);
        for (int round = 0; round < 2; ++round) {
            EXPECT_TRUE(same(obbsat::find_pairs(large, options), want_large)) << "threads " << threads;
            EXPECT_TRUE(same(obbsat::find_pairs(small, options), want_small)) << "threads " << threads;
            EXPECT_TRUE(same(obbsat::find_pairs(small, b_side, options), want_cross)) << "threads " << threads;
            EXPECT_TRUE(same(obbsat::find_pairs(other, options), want_other)) << "threads " << threads;
            EXPECT_GT(obbsat::detail::spare_search_bytes(), 0u);
        }
    }
    obbsat::release_scratch();
}

TEST(SpareSearch, QueriesAtOnceEachAnswerTheirOwn) {
    const std::vector<rect_pose> first = scene_of(20000, obbsat::scene_sizes::uniform, 8);
    const std::vector<rect_pose> second = scene_of(12000, obbsat::scene_sizes::mixed, 9);
    const obbsat::collide_options options = options_of(1);
    const std::vector<pair_index> want_first = fresh_answer(first, options);
    const std::vector<pair_index> want_second = fresh_answer(second, options);
    constexpr int rounds = 8;
    int wrong_first = 0;
    int wrong_second = 0;
    std::thread other([&] {
        for (int i = 0; i < rounds; ++i) {
            wrong_second += same(obbsat::find_pairs(second, options), want_second) ? 0 : 1;
        }
    });
    for (int i = 0; i < rounds; ++i) {
        wrong_first += same(obbsat::find_pairs(first, options), want_first) ? 0 : 1;
        if (i == rounds / 2) {
            obbsat::release_scratch();  // while the other thread may be querying
        }
    }
    other.join();
    EXPECT_EQ(wrong_first, 0);
    EXPECT_EQ(wrong_second, 0);
    obbsat::release_scratch();
    EXPECT_EQ(obbsat::detail::spare_search_bytes(), 0u);
}

TEST(SpareSearch, ReleaseScratchLeavesFindContactsAnswering) {
    const std::vector<rect_pose> boxes = scene_of(5000, obbsat::scene_sizes::uniform, 10);
    const obbsat::collide_options options = options_of(1);
    const obbsat::scene_contacts before = obbsat::find_contacts(boxes, options, 0.0f);
    obbsat::release_scratch();
    const obbsat::scene_contacts after = obbsat::find_contacts(boxes, options, 0.0f);
    EXPECT_TRUE(same(before.pairs, after.pairs));
    EXPECT_FALSE(after.pairs.empty());
}

/// A scene of rect_pose64 rows far from the origin (UTM-like coordinates),
/// each center off the float grid, so that the query's float stand-ins and
/// its double decisions both have work to do.
std::vector<rect_pose64> double_scene_of(std::size_t boxes, obbsat::scene_sizes sizes, std::uint64_t seed) {
    std::vector<rect_pose64> rows;
    for (const rect_pose& p : scene_of(boxes, sizes, seed)) {
        const double nudge = 0x1p-20 * static_cast<double>(rows.size() % 7);
        rows.push_back({{500000.125 + p.center.x + nudge, 5712345.5 + p.center.y - nudge},
                        {p.half_extents.x, p.half_extents.y},
                        {p.rotation.x, p.rotation.y}});
    }
    return rows;
}

/// Same pairs and the same contacts bit for bit.
bool same(const obbsat::scene_contacts64& x, const obbsat::scene_contacts64& y) {
    return same(x.pairs, y.pairs) && x.contacts.size() == y.contacts.size() &&
           std::equal(x.contacts.begin(), x.contacts.end(), y.contacts.begin(),
                      [](const obbsat::contact64& p, const obbsat::contact64& q) {
                          return std::memcmp(&p, &q, sizeof p) == 0;
                      });
}

TEST(SpareSearch, DoubleQueriesKeepTheirMemoryAndReleaseScratchFreesIt) {
    const std::vector<rect_pose64> boxes = double_scene_of(20000, obbsat::scene_sizes::uniform, 11);
    obbsat::release_scratch();
    EXPECT_EQ(obbsat::detail::spare_search_bytes(), 0u);
    EXPECT_EQ(obbsat::detail::kept_contacts_record_bytes(), 0u);
    const obbsat::scene_contacts64 found = obbsat::find_contacts64(boxes, options_of(1));
    ASSERT_FALSE(found.pairs.empty());
    // The query's double records in its order (64 bytes a box) and the float
    // stand-ins of the double rows (32 bytes a box), at least.
    EXPECT_GE(obbsat::detail::spare_search_bytes(), 96u * boxes.size());
    // The caller's rect_pose64 rows as the records the contact kernels read.
    EXPECT_GE(obbsat::detail::kept_contacts_record_bytes(), 64u * boxes.size());
    const std::size_t contacts_query_bytes = obbsat::detail::spare_search_bytes();
    obbsat::release_scratch();
    EXPECT_EQ(obbsat::detail::spare_search_bytes(), 0u);
    EXPECT_EQ(obbsat::detail::kept_contacts_record_bytes(), 0u);
    // find_pairs on the same rows keeps the same working memory, the float
    // stand-ins of the double rows included.
    EXPECT_TRUE(same(obbsat::find_pairs(boxes, options_of(1)), found.pairs));
    EXPECT_GE(obbsat::detail::spare_search_bytes(), contacts_query_bytes);
    obbsat::release_scratch();
    EXPECT_EQ(obbsat::detail::spare_search_bytes(), 0u);
}

TEST(SpareSearch, DoubleAnswersInBorrowedMemoryAreThoseOfFreshMemory) {
    // Double scenes of other sizes, float ones and contacts one after the
    // other, each call borrowing what the last one left: larger records,
    // another scene's stand-ins and order, a caller's answer kept or fresh.
    const std::vector<rect_pose64> large = double_scene_of(30000, obbsat::scene_sizes::mixed, 12);
    const std::vector<rect_pose64> small = double_scene_of(3000, obbsat::scene_sizes::uniform, 13);
    const std::vector<rect_pose64> other = double_scene_of(20000, obbsat::scene_sizes::uniform, 14);
    const std::vector<rect_pose> floats = scene_of(25000, obbsat::scene_sizes::uniform, 15);
    for (const unsigned threads : {1u, 2u, 3u}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const obbsat::collide_options options = options_of(threads);
        obbsat::release_scratch();
        const obbsat::scene_contacts64 want_large = obbsat::find_contacts64(large, options);
        obbsat::release_scratch();
        const obbsat::scene_contacts64 want_small = obbsat::find_contacts64(small, options);
        obbsat::release_scratch();
        const obbsat::scene_contacts64 want_other = obbsat::find_contacts64(other, options);
        const std::vector<pair_index> want_floats = fresh_answer(floats, options);
        ASSERT_GT(want_large.pairs.size(), 2 * want_small.pairs.size());
        obbsat::scene_contacts64 kept;
        for (int round = 0; round < 2; ++round) {
            obbsat::find_contacts(small, options, 0.0, kept);
            EXPECT_TRUE(same(kept, want_small));
            EXPECT_TRUE(same(obbsat::find_contacts64(large, options), want_large));
            EXPECT_TRUE(same(obbsat::find_pairs(floats, options), want_floats));
            obbsat::find_contacts(large, options, 0.0, kept);
            EXPECT_TRUE(same(kept, want_large));
            EXPECT_TRUE(same(obbsat::find_pairs(other, options), want_other.pairs));
            EXPECT_TRUE(same(obbsat::find_contacts64(small, options), want_small));
            obbsat::find_contacts(other, options, 0.0, kept);
            EXPECT_TRUE(same(kept, want_other));
            EXPECT_GE(obbsat::detail::kept_contacts_record_bytes(), 64u * large.size());
        }
    }
    obbsat::release_scratch();
}

}  // namespace
