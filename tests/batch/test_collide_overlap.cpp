// The pair-list entry points refuse a verdict buffer that shares memory with
// the pairs, or with the rectangles or poses they read in place: the verdicts
// of one part would overwrite indices or coordinates another part has yet to
// read. The refusal is invalid_input naming both buffers, and nothing is
// written. Buffers that only touch (one ends where the other starts) are fine.
//
// The scenes are chosen so that, were the overlap not refused, every verdict
// written over an index would keep it in range (all pairs apart: verdict 0),
// so the unchecked call would run to its end rather than read out of bounds.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

namespace {

using obbsat::pair_index;
using obbsat::rect;
using obbsat::rect_pose;

constexpr std::size_t box_count = 64;
constexpr std::size_t pair_count = 4096;

/// Unit squares ten apart along x: no two collide.
std::vector<rect> apart_rects() {
    std::vector<rect> rects;
    for (std::size_t i = 0; i < box_count; ++i) {
        const float x = 10.0f * static_cast<float>(i);
        rects.push_back(rect{{x, 1}, {x + 1, 1}, {x + 1, 0}, {x, 0}});
    }
    return rects;
}

/// The same squares as poses.
std::vector<rect_pose> apart_poses() {
    std::vector<rect_pose> poses;
    for (std::size_t i = 0; i < box_count; ++i) {
        poses.push_back(rect_pose{{10.0f * static_cast<float>(i) + 0.5f, 0.5f}, {0.5f, 0.5f}, {1, 0}});
    }
    return poses;
}

/// Bytes holding `pair_count` pairs (i, i + 1) of distinct boxes from offset 0,
/// with room after them for `pair_count` verdicts.
struct shared_bytes {
    std::vector<std::uint64_t> words;
    shared_bytes() : words(pair_count + pair_count / 8 + 1, 0) {
        for (std::size_t i = 0; i < pair_count; ++i) {
            const std::uint32_t a = static_cast<std::uint32_t>(i % box_count);
            pairs()[i] = pair_index{a, static_cast<std::uint32_t>((a + 1) % box_count)};
        }
    }
    pair_index* pairs() { return reinterpret_cast<pair_index*>(words.data()); }
    std::uint8_t* bytes() { return reinterpret_cast<std::uint8_t*>(words.data()); }
    std::vector<std::uint8_t> snapshot() const {
        std::vector<std::uint8_t> copy(words.size() * sizeof(std::uint64_t));
        std::memcpy(copy.data(), words.data(), copy.size());
        return copy;
    }
};

obbsat::collide_options options_with(obbsat::method m) {
    obbsat::collide_options options;
    options.test = m;
    options.threads = 1;
    return options;
}

/// Runs `call`, which must throw invalid_input whose text names both buffers.
template <class Call>
void expect_refused(const Call& call, const std::string& other) {
    try {
        call();
        ADD_FAILURE() << "no exception: verdicts overlapping " << other << " were accepted";
    } catch (const obbsat::invalid_input& e) {
        const std::string text = e.what();
        EXPECT_NE(text.find("verdicts"), std::string::npos) << text;
        EXPECT_NE(text.find(other), std::string::npos) << text;
    }
}

/// Every store a pair-list entry reads, over the same apart boxes.
struct apart_stores {
    std::vector<rect> rects = apart_rects();
    std::vector<rect_pose> poses = apart_poses();
    obbsat::rect_records records{rects};
    obbsat::rect_soa soa{rects};
    obbsat::pose_records pose_store{poses};
};

using pair_list_call = void (*)(const apart_stores&, const pair_index*, std::uint8_t*);

TEST(CollideOverlap, VerdictsOverThePairsAreRefusedByEveryPairListEntry) {
    const apart_stores stores;
    const pair_list_call entries[] = {
        [](const apart_stores& s, const pair_index* pairs, std::uint8_t* out) {
            obbsat::collide_pairs(s.records, pairs, pair_count, out, options_with(obbsat::method::sat4));
        },
        [](const apart_stores& s, const pair_index* pairs, std::uint8_t* out) {
            obbsat::collide_pairs(s.rects.data(), s.rects.size(), pairs, pair_count, out,
                                  options_with(obbsat::method::sat4));
        },
        [](const apart_stores& s, const pair_index* pairs, std::uint8_t* out) {
            obbsat::collide_pairs(s.soa, pairs, pair_count, out, options_with(obbsat::method::sat4));
        },
        [](const apart_stores& s, const pair_index* pairs, std::uint8_t* out) {
            obbsat::collide_pairs(s.pose_store, pairs, pair_count, out, options_with(obbsat::method::local));
        },
        [](const apart_stores& s, const pair_index* pairs, std::uint8_t* out) {
            obbsat::collide_pairs(s.poses.data(), s.poses.size(), pairs, pair_count, out,
                                  options_with(obbsat::method::local));
        },
    };
    // The verdicts start on the last pair, on its last byte, on the first pair;
    // each call gets pairs of its own.
    for (const std::size_t start : {8 * pair_count - 8, 8 * pair_count - 1, std::size_t{0}}) {
        for (std::size_t entry = 0; entry < std::size(entries); ++entry) {
            shared_bytes memory;
            const std::vector<std::uint8_t> before = memory.snapshot();
            expect_refused([&] {
                entries[entry](stores, memory.pairs(), memory.bytes() + start);
            }, "pairs");
            EXPECT_EQ(memory.snapshot(), before) << "entry " << entry << ", verdicts from byte " << start;
        }
    }
}

TEST(CollideOverlap, VerdictsOverTheRowsReadInPlaceAreRefused) {
    shared_bytes memory;
    const pair_index* pairs = memory.pairs();
    // Rectangles followed by room for the verdicts, which start in the middle of the rectangles.
    std::vector<std::uint64_t> rect_words((box_count * sizeof(rect) + pair_count) / 8, 0);
    rect* rects = reinterpret_cast<rect*>(rect_words.data());
    const std::vector<rect> apart_corners = apart_rects();
    std::memcpy(rects, apart_corners.data(), apart_corners.size() * sizeof(rect));
    expect_refused([&] {
        obbsat::collide_pairs(rects, box_count, pairs, pair_count,
                              reinterpret_cast<std::uint8_t*>(rects + box_count / 2),
                              options_with(obbsat::method::sat4));
    }, "rects");
    EXPECT_EQ(std::memcmp(rects, apart_corners.data(), apart_corners.size() * sizeof(rect)), 0);

    // Poses followed by room for the verdicts; the verdicts start on the last pose.
    std::vector<std::uint64_t> words((box_count * sizeof(rect_pose) + pair_count) / 8 + 1, 0);
    rect_pose* poses = reinterpret_cast<rect_pose*>(words.data());
    const std::vector<rect_pose> apart = apart_poses();
    std::memcpy(poses, apart.data(), apart.size() * sizeof(rect_pose));
    expect_refused([&] {
        obbsat::collide_pairs(poses, box_count, pairs, pair_count,
                              reinterpret_cast<std::uint8_t*>(poses + box_count - 1),
                              options_with(obbsat::method::local));
    }, "poses");
    EXPECT_EQ(std::memcmp(poses, apart.data(), apart.size() * sizeof(rect_pose)), 0);
}

TEST(CollideOverlap, BuffersThatOnlyTouchAreAccepted) {
    shared_bytes memory;
    pair_index* pairs = memory.pairs();
    std::uint8_t* verdicts = memory.bytes() + pair_count * sizeof(pair_index);  // right after the last pair
    const std::vector<rect> rects = apart_rects();
    const obbsat::rect_records records(rects);
    for (const unsigned threads : {1u, 2u}) {
        obbsat::collide_options options = options_with(obbsat::method::sat4);
        options.threads = threads;
        std::memset(verdicts, 0xa5, pair_count);
        obbsat::collide_pairs(records, pairs, pair_count, verdicts, options);
        for (std::size_t i = 0; i < pair_count; ++i) {
            ASSERT_EQ(verdicts[i], 0) << "pair " << i;
        }
    }
    // Verdicts ending where the rows begin.
    std::vector<std::uint64_t> words((pair_count + box_count * sizeof(rect)) / 8, 0);
    std::uint8_t* before_rows = reinterpret_cast<std::uint8_t*>(words.data());
    rect* rows = reinterpret_cast<rect*>(before_rows + pair_count);
    std::memcpy(rows, rects.data(), rects.size() * sizeof(rect));
    obbsat::collide_pairs(rows, box_count, pairs, pair_count, before_rows, options_with(obbsat::method::sat4));
    for (std::size_t i = 0; i < pair_count; ++i) {
        ASSERT_EQ(before_rows[i], 0) << "pair " << i;
    }
}

}  // namespace
