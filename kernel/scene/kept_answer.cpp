// pair_finder's kept candidates (kept_pairs.hpp): their test, and the answer read from them in the caller's order.
#include "scene/pair_search.hpp"

#include "scene/search_common.hpp"
#include "support/bit_width.hpp"
#include "support/work_shares.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace obbsat::detail {

namespace {

/// 1 iff the bounds a and b, each (lo_x, lo_y, -hi_x, -hi_y), overlap (closed
/// intervals): b's lo is at most a's hi and a's lo at most b's hi on both
/// axes, that is b <= (a.hi_x, a.hi_y, -a.lo_x, -a.lo_y) in every place.
/// Negation is exact, so this is the sweep's test, comparison for comparison.
unsigned signed_bounds_overlap(const float* a, const float* b) {
#if defined(__SSE2__)
    const __m128 va = _mm_loadu_ps(a);
    const __m128 vb = _mm_loadu_ps(b);
    const __m128 swapped = _mm_shuffle_ps(va, va, _MM_SHUFFLE(1, 0, 3, 2));
    const __m128 reach = _mm_xor_ps(swapped, _mm_set1_ps(-0.0f));
    return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(vb, reach)) == 15);
#else
    return static_cast<unsigned>(b[0] <= -a[2]) & static_cast<unsigned>(b[1] <= -a[3]) &
           static_cast<unsigned>(b[2] <= -a[0]) & static_cast<unsigned>(b[3] <= -a[1]);
#endif
}
/// Verdicts v[0, n), each 0 or 1, n <= 64, as one word: bit i is v[i].
std::uint64_t verdict_word(const std::uint8_t* v, std::size_t n) {
    std::uint64_t word = 0;
#ifdef __SSE2__
    if (n == 64) {
        for (unsigned k = 0; k < 4; ++k) {
            // A 0/1 byte shifted left by 7 is its own sign bit.
            const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(v + 16 * k));
            const auto mask = static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_slli_epi16(bytes, 7)));
            word |= static_cast<std::uint64_t>(mask) << (16 * k);
        }
        return word;
    }
#endif
    for (std::size_t i = 0; i < n; ++i) {
        word |= static_cast<std::uint64_t>(v[i]) << i;
    }
    return word;
}

}  // namespace

void pair_search::mark_answer_shares(std::size_t parts) {
    if (kept_.answer_parts == parts) {
        return;
    }
    const std::size_t words = (kept_.pairs.size() + 63) / 64;
    kept_.answer_marks.resize(words * (parts - 1));
    run_parts(parts, [&](std::size_t share) {
        if (share == 0) {
            return;
        }
        std::uint64_t* const marks = kept_.answer_marks.data() + (share - 1) * words;
        std::fill(marks, marks + words, std::uint64_t{0});
        const auto [begin, end] = share_of(kept_.by_caller.size(), share, parts);
        const tagged_pair* const kept = kept_.by_caller.data();
        for (std::size_t j = begin; j < end; ++j) {
            if (!kept_pairs::is_gap(kept[j])) {
                marks[kept[j].tag / 64] |= std::uint64_t{1} << (kept[j].tag % 64);
            }
        }
    });
    kept_.answer_parts = parts;
}

void pair_search::test_kept(std::size_t parts, bool unfiltered, std::size_t shares) {
    // The kept candidates whose bounds overlap now, by the sweep's own test,
    // are the candidates a sweep would find; the method decides them, or,
    // `unfiltered`, every kept candidate.
    const auto start = clock_type::now();
    if (parts_.size() < parts) {
        parts_.resize(parts);
    }
    const std::size_t words = (kept_.pairs.size() + 63) / 64;
    kept_.verdicts.resize(words + 1);
    kept_.verdicts[words] = 0;  // the verdict of gap entries (kept_pairs::gap_pair)
    mark_answer_shares(shares);
    const signed_bounds* const now = kept_.now.data();
    run_parts(parts, [&](std::size_t share) {
        part& p = parts_[share];
        p.keep.colliding_in_share.assign(shares, 0);
        if (p.candidates.size() < candidate_block) {
            p.candidates.resize(candidate_block);
            p.verdicts.resize(candidate_block);
        }
        p.keep.slots.resize(candidate_block);
        p.tested = 0;
        p.keep.colliding = 0;
        p.slow_path = 0;
        p.kernel_seconds = 0;
        const auto [begin, end] = aligned_share_of(kept_.pairs.size(), share, parts, 64);
        // Plain pointers: a byte store may alias anything, and the vectors'
        // own pointers would be reloaded on every candidate.
        const pair_index* const kept = kept_.pairs.data();
        const std::uint64_t* const dropped = kept_.dropped.data();
        const std::size_t dropped_words = kept_.dropped.size();
        std::uint64_t* const verdict_words = kept_.verdicts.data();
        const std::uint64_t* const marks = kept_.answer_marks.data();
        std::size_t* const in_share = p.keep.colliding_in_share.data();
        pair_index* const candidates = p.candidates.data();
        std::uint32_t* const slots = p.keep.slots.data();
        // One block's verdicts, in the kept order, before they become bits.
        alignas(64) std::uint8_t verdicts[candidate_block];
        static_assert(candidate_block % 64 == 0, "blocks start on a word of the kept verdicts");
        for (std::size_t first = begin; first < end; first += candidate_block) {
            const std::size_t last = std::min(end, first + candidate_block);
            // The verdicts as bits, those of pairs of gone rows (kept_changes.cpp)
            // cleared: they are tested with the rest, on records far from
            // everything, and never answer.
            const auto keep_bits = [&] {
                const std::size_t n = last - first;
                for (std::size_t w = 0; 64 * w < n; ++w) {
                    const std::size_t in_word = std::min<std::size_t>(64, n - 64 * w);
                    const std::size_t word = first / 64 + w;
                    std::uint64_t bits = verdict_word(verdicts + 64 * w, in_word);
                    bits &= word < dropped_words ? ~dropped[word] : ~std::uint64_t{0};
                    verdict_words[word] = bits;
                    p.keep.colliding += bits_set(bits);
                    for (std::size_t s = 1; s < shares; ++s) {
                        in_share[s] += bits_set(bits & marks[(s - 1) * words + word]);
                    }
                }
            };
            if (unfiltered) {
                test_pairs(p, kept + first, last - first, verdicts);
                keep_bits();
                continue;
            }
            std::size_t count = 0;
            for (std::size_t i = first; i < last; ++i) {
                const unsigned overlap = signed_bounds_overlap(now[kept[i].a].v, now[kept[i].b].v);
                candidates[count] = kept[i];
                slots[count] = static_cast<std::uint32_t>(i - first);
                count += overlap;
            }
            std::memset(verdicts, 0, last - first);
            test_candidates(p, count);
            const std::uint8_t* const tested = p.verdicts.data();
            for (std::size_t c = 0; c < count; ++c) {
                verdicts[slots[c]] = tested[c];
            }
            keep_bits();
        }
    });
    for (std::size_t i = 0; i < parts; ++i) {
        stats_.candidates += parts_[i].tested;
        stats_.slow_path_pairs += parts_[i].slow_path;
        stats_.kernel_seconds += parts_[i].kernel_seconds;
    }
    if (options_.slow_path_pairs != nullptr) {
        *options_.slow_path_pairs = stats_.slow_path_pairs;
    }
    stats_.sweep_seconds += seconds_since(start);
}

void pair_search::answer_from_kept(std::size_t parts) {
    // The kept pairs are sorted in the caller's indices: the answer is the
    // ones the method called colliding, read in that order. The test counted
    // the colliding pairs of each share (mark_answer_shares), so each share
    // writes its pairs where they belong in the answer and stops at its last:
    // no write past its place, no copy.
    const auto start = clock_type::now();
    // Colliding pairs of each share: the later ones counted by the test, the
    // first one what is left of all.
    std::vector<std::size_t> in_share(parts, 0);
    std::size_t colliding = 0;
    for (std::size_t i = 0; i < parts; ++i) {
        colliding += parts_[i].keep.colliding;
        for (std::size_t share = 1; share < parts; ++share) {
            in_share[share] += parts_[i].keep.colliding_in_share[share];
        }
    }
    in_share[0] = colliding - std::accumulate(in_share.begin() + 1, in_share.end(), std::size_t{0});
    std::vector<std::size_t> offsets(parts + 1, 0);
    std::partial_sum(in_share.begin(), in_share.end(), offsets.begin() + 1);
    pairs_.resize(colliding);
    std::vector<std::size_t> found_in(parts, 0);
    const std::size_t kept_count = kept_.by_caller.size();
    run_parts(parts, [&](std::size_t share) {
        // Named apart, not bound: the step below captures them.
        const std::pair<std::size_t, std::size_t> range = share_of(kept_count, share, parts);
        const std::size_t begin = range.first;
        const std::size_t end = range.second;
        pair_index* const out = pairs_.data() + offsets[share];
        const std::size_t wanted = offsets[share + 1] - offsets[share];
        const std::uint64_t* const verdict_words = kept_.verdicts.data();
        const tagged_pair* const kept = kept_.by_caller.data();
        std::size_t found = 0;
        constexpr std::size_t ahead = 64;
        // Each kept pair is written where the next colliding one goes, and
        // counted if it collides: no branch on the verdicts. A pair is
        // written at most `step` places past the last counted one, so whole
        // steps run unchecked while that stays inside the share.
        const auto take = [&](std::size_t j) __attribute__((always_inline)) {
            if (j + ahead < end) {
                __builtin_prefetch(verdict_words + kept[j + ahead].tag / 64);
            }
            out[found] = pair_index{kept[j].a, kept[j].b};
            const std::uint32_t tag = kept[j].tag;
            found += static_cast<std::size_t>((verdict_words[tag / 64] >> (tag % 64)) & 1u);
        };
        constexpr std::size_t step = 64;
        std::size_t j = begin;
        for (; end - j >= step && wanted - found >= step; j += step) {
            for (std::size_t k = j; k < j + step; ++k) {
                take(k);
            }
        }
        for (; j < end && found < wanted; ++j) {
            take(j);
        }
        found_in[share] = found;
    });
    for (std::size_t share = 0; share < parts; ++share) {
        if (found_in[share] != offsets[share + 1] - offsets[share]) {
            throw std::logic_error("obbsat: a share of the answer from kept candidates found " +
                                   std::to_string(found_in[share]) + " colliding pairs where the test counted " +
                                   std::to_string(offsets[share + 1] - offsets[share]));
        }
    }
    stats_.pairs = pairs_.size();
    stats_.output_seconds += seconds_since(start);
}

}  // namespace obbsat::detail
