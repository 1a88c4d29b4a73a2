// A repeated scene query works in the memory the last one left: a warm
// find_pairs allocates its answer and little else, on one thread and on two
// (the buckets of the order's sort on two threads included: they are sorted
// in buffers the query keeps, kernel/support/unit_buffers.hpp), and nothing
// for its answer when it writes into the caller's vector; a pair_finder
// frame answered from its kept candidates allocates nothing large, and the
// answers on scenes growing and shrinking are those of a query in fresh
// memory. The allocations are counted by this binary's operator new.
#include <obbsat/collide.hpp>
#include <obbsat/error.hpp>
#include <obbsat/find_pairs.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <new>
#include <vector>

namespace {

/// Blocks of at least this many bytes are counted: a scene's arrays and the
/// sort's buckets, not the small bookkeeping of a call.
constexpr std::size_t counted_block = 8192;

std::atomic<std::size_t> counted_bytes{0};
std::atomic<std::size_t> counted_blocks{0};

void note(std::size_t bytes) {
    if (bytes >= counted_block) {
        counted_bytes.fetch_add(bytes, std::memory_order_relaxed);
        counted_blocks.fetch_add(1, std::memory_order_relaxed);
    }
}

void* allocate(std::size_t bytes, std::size_t alignment) {
    note(bytes);
    void* block = alignment <= alignof(std::max_align_t)
                      ? std::malloc(bytes == 0 ? 1 : bytes)
                      : std::aligned_alloc(alignment, (bytes + alignment - 1) / alignment * alignment);
    if (block == nullptr) {
        throw std::bad_alloc();
    }
    return block;
}

}  // namespace

// GCC 12 sees free() in a replacement operator delete as a mismatch with the
// operator new it replaces; here both sides are this file's malloc and free.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

void* operator new(std::size_t bytes) { return allocate(bytes, 0); }
void* operator new[](std::size_t bytes) { return allocate(bytes, 0); }
void* operator new(std::size_t bytes, std::align_val_t alignment) {
    return allocate(bytes, static_cast<std::size_t>(alignment));
}
void* operator new[](std::size_t bytes, std::align_val_t alignment) {
    return allocate(bytes, static_cast<std::size_t>(alignment));
}
void operator delete(void* block) noexcept { std::free(block); }
void operator delete[](void* block) noexcept { std::free(block); }
void operator delete(void* block, std::size_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t) noexcept { std::free(block); }
void operator delete(void* block, std::align_val_t) noexcept { std::free(block); }
void operator delete[](void* block, std::align_val_t) noexcept { std::free(block); }
void operator delete(void* block, std::size_t, std::align_val_t) noexcept { std::free(block); }
void operator delete[](void* block, std::size_t, std::align_val_t) noexcept { std::free(block); }

namespace {

using obbsat::pair_index;
using obbsat::rect_pose;

/// Bytes in counted blocks that `call` allocated.
template <class Call>
std::size_t counted_bytes_of(const Call& call) {
    const std::size_t before = counted_bytes.load();
    call();
    return counted_bytes.load() - before;
}

std::vector<rect_pose> scene_of(std::size_t boxes, std::uint64_t seed) {
    obbsat::pose_scene_spec spec;
    spec.boxes = boxes;
    spec.seed = seed;
    return obbsat::make_pose_scene(spec);
}

obbsat::collide_options options_of(unsigned threads) {
    obbsat::collide_options options;
    options.test = obbsat::method::local;
    options.threads = threads;
    return options;
}

bool same(const std::vector<pair_index>& x, const std::vector<pair_index>& y) {
    return std::equal(x.begin(), x.end(), y.begin(), y.end(),
                      [](const pair_index& p, const pair_index& q) { return p.a == q.a && p.b == q.b; });
}

// Enough boxes for the order's sort to take two threads (two shares of at
// least 32768 keys) and split into buckets.
const std::size_t boxes = 150000;

TEST(QueryMemory, AWarmFindPairsAllocatesItsAnswerAndLittleElse) {
    const obbsat::pose_records poses(scene_of(boxes, 41));
    for (const unsigned threads : {1u, 2u}) {
        const obbsat::collide_options options = options_of(threads);
        obbsat::release_scratch();
        std::vector<pair_index> pairs;
        const std::size_t cold = counted_bytes_of([&] { pairs = obbsat::find_pairs(poses, options); });
        ASSERT_FALSE(pairs.empty());
        const std::size_t answer = pairs.size() * sizeof(pair_index);
        pairs = {};
        const std::size_t warm = counted_bytes_of([&] { pairs = obbsat::find_pairs(poses, options); });
        // A cold query allocates its records (32 bytes a box) and more.
        EXPECT_GT(cold, answer + 32 * boxes) << "threads " << threads;
        // A warm one its answer, and the counts of the sort's units (a few
        // KiB each): no bucket of the sort allocates.
        EXPECT_LE(warm, answer + (256u << 10)) << "threads " << threads << ", answer " << answer;
    }
    obbsat::release_scratch();
}

TEST(QueryMemory, AWarmFindPairsIntoTheCallersVectorAllocatesNoAnswer) {
    const std::vector<rect_pose> rows = scene_of(boxes, 44);
    const obbsat::pose_records poses(rows);
    const obbsat::box_view a(rows.data(), boxes / 2);
    const obbsat::box_view b(rows.data() + boxes / 2, boxes - boxes / 2);
    for (const unsigned threads : {1u, 2u}) {
        const obbsat::collide_options options = options_of(threads);
        const std::vector<pair_index> want = obbsat::find_pairs(poses, options);
        const std::vector<pair_index> want_cross = obbsat::find_pairs(a, b, options);
        std::vector<pair_index> out;
        obbsat::find_pairs(poses, options, out);
        EXPECT_TRUE(same(out, want)) << "threads " << threads;
        const pair_index* const held = out.data();
        const std::size_t warm = counted_bytes_of([&] { obbsat::find_pairs(poses, options, out); });
        EXPECT_TRUE(same(out, want)) << "threads " << threads;
        EXPECT_EQ(out.data(), held) << "threads " << threads;
        // One thread: nothing; two: the counts of the sort's units.
        EXPECT_LE(warm, threads == 1 ? 0u : (256u << 10)) << "threads " << threads;
        obbsat::find_pairs(a, b, options, out);
        EXPECT_TRUE(same(out, want_cross)) << "threads " << threads;
    }
    // A row refused leaves `out` as it was.
    std::vector<rect_pose> bad = rows;
    bad[boxes / 3].center.x = std::numeric_limits<float>::quiet_NaN();
    std::vector<pair_index> out = obbsat::find_pairs(poses, options_of(1));
    const std::vector<pair_index> before = out;
    EXPECT_THROW(obbsat::find_pairs(bad, options_of(1), out), obbsat::invalid_input);
    EXPECT_TRUE(same(out, before));
    obbsat::release_scratch();
}

TEST(QueryMemory, APairFinderFrameFromKeptCandidatesAllocatesNothingLarge) {
    std::vector<rect_pose> rows = scene_of(boxes, 42);
    for (const unsigned threads : {1u, 2u}) {
        obbsat::pair_finder finder(options_of(threads));
        for (int frame = 0; frame < 6; ++frame) {
            // A small drift, well inside the kept candidates' margin.
            for (rect_pose& p : rows) {
                p.center.x += frame % 2 == 0 ? 1e-3f : -1e-3f;
            }
            const obbsat::pose_records poses(rows);
            std::size_t found = 0;
            const std::size_t bytes = counted_bytes_of([&] { found = finder.find(poses).size(); });
            EXPECT_GT(found, 0u);
            if (frame >= 3) {
                EXPECT_EQ(bytes, 0u) << "threads " << threads << ", frame " << frame;
            }
        }
    }
}

TEST(QueryMemory, AnswersOnScenesGrowingAndShrinkingAreThoseOfFreshMemory) {
    const std::vector<rect_pose> all = scene_of(2 * boxes, 43);
    const std::size_t sizes[] = {boxes, boxes / 2, 2 * boxes, 70000, boxes};
    for (const unsigned threads : {1u, 2u}) {
        const obbsat::collide_options options = options_of(threads);
        std::vector<std::vector<pair_index>> fresh;
        for (const std::size_t n : sizes) {
            obbsat::release_scratch();
            fresh.push_back(obbsat::find_pairs(obbsat::box_view(all.data(), n), options));
        }
        obbsat::pair_finder finder(options);
        for (int round = 0; round < 2; ++round) {
            for (std::size_t i = 0; i < std::size(sizes); ++i) {
                const obbsat::box_view view(all.data(), sizes[i]);
                EXPECT_TRUE(same(obbsat::find_pairs(view, options), fresh[i]))
                    << "find_pairs, threads " << threads << ", " << sizes[i] << " boxes";
                EXPECT_TRUE(same(finder.find(view), fresh[i]))
                    << "pair_finder, threads " << threads << ", " << sizes[i] << " boxes";
            }
        }
    }
    obbsat::release_scratch();
}

}  // namespace
