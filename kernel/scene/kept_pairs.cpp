// pair_finder's kept candidates (kept_pairs.hpp): the steps of the persistent query that answers from them.
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "scene/search_common.hpp"
#include "sort/pair_sort.hpp"
#include "support/bit_width.hpp"
#include "support/fetch_ahead.hpp"
#include "support/work_shares.hpp"

#include <obbsat/method.hpp>

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

/// Writes `count` 32-byte records from `from` to `to` (both 16-byte aligned)
/// with non-temporal stores where the CPU has them: lines written whole are
/// not read in first. finish_streams orders them before what follows.
template <class Record>
void stream_records(const Record* from, std::size_t count, Record* to) {
    static_assert(sizeof(Record) == 32, "two 16-byte stores a record");
#if defined(__SSE2__)
    for (std::size_t k = 0; k < count; ++k) {
        _mm_stream_ps(to[k].v, _mm_load_ps(from[k].v));
        _mm_stream_ps(to[k].v + 4, _mm_load_ps(from[k].v + 4));
    }
#else
    std::memcpy(to, from, count * sizeof(Record));
#endif
}

void finish_streams() {
#if defined(__SSE2__)
    _mm_sfence();
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

/// How many of `count` verdicts (each 0 or 1) say colliding.
std::size_t count_colliding(const std::uint8_t* verdicts, std::size_t count) {
    std::size_t sum = 0;
    for (std::size_t i = 0; i < count; ++i) {
        sum += verdicts[i];
    }
    return sum;
}

}  // namespace

const std::vector<pair_index>& pair_search::collect(const query_input& input) {
    set_query(input);
    const std::size_t parts = parts_for(n_, options_.threads, min_boxes_per_part);
    if (kept_.ready && same_scene_as_last() && n_ >= 2) {
        const auto start = clock_type::now();
        // An exact method calls a pair colliding only if the two rectangles
        // share a point, so only if their bounds overlap (the bounds hold the
        // rectangles): its verdict on a kept pair whose bounds do not overlap
        // is false, the answer of leaving the pair out. It tests every kept
        // pair, which costs less than the filter, and needs no bounds of this
        // call beyond the check that they fit.
        const bool exact = guarantee_of(options_.test) == method_guarantee::exact;
        const bool fits = refresh_records(input, parts, !exact);
        stats_.bounds_seconds = seconds_since(start);
        if (fits) {
            ++kept_.calls;
            stats_.reused_order = true;
            stats_.reused_candidates = true;
            stats_.kept_candidates = kept_.pairs.size();
            stats_.strips = grid_.strips;
            stats_.visits = visit_keys_.size() - 1;
            used_parts_ = parts;
            test_kept(parts, exact);
            answer_from_kept(parts);
            return pairs_;
        }
    }
    // A full query that keeps its candidates. The margin follows the motion:
    // kept candidates that served only a few calls widen the next ones, and
    // candidates that outlived many calls narrow them.
    if (kept_.ready && kept_.margin > 0.0f) {
        if (kept_.calls < 4) {
            kept_.margin_share = std::min(kept_.margin_share * 2, 1.0 / 2);
        } else if (kept_.calls > 64) {
            kept_.margin_share = std::max(kept_.margin_share / 2, 1.0 / 256);
        }
    }
    kept_.ready = false;
    kept_.calls = 0;
    if (!same_scene_as_last()) {
        // The first call on a scene knows no motion yet, and pairs kept from
        // bounds not widened would serve no call after a move: it answers
        // as a plain query, and the next call keeps the pairs of widened bounds.
        return answer_plainly(input);
    }
    kept_.margin = static_cast<float>(kept_.margin_share);
    kept_.keep = true;
    try {
        run(input, pair_chunk_sink{});
    } catch (...) {
        kept_.keep = false;
        throw;
    }
    kept_.keep = false;
    if (used_parts_ == 0) {
        pairs_.clear();
        return pairs_;
    }
    bool over_budget = false;
    for (std::size_t i = 0; i < used_parts_; ++i) {
        over_budget |= parts_[i].keep.over_budget;
    }
    if (over_budget) {
        // The widened bounds met too many others: this call answers as a
        // plain query, and the next full query widens less.
        for (std::size_t i = 0; i < used_parts_; ++i) {
            std::vector<pair_index>().swap(parts_[i].keep.captured);
        }
        kept_.margin_share = std::max(kept_.margin_share / 4, 1.0 / 256);
        return answer_plainly(input);
    }
    keep_candidates(used_parts_);
    kept_.ready = true;
    test_kept(used_parts_, false);
    kept_.last_candidates = stats_.candidates;
    answer_from_kept(used_parts_);
    return pairs_;
}

bool pair_search::refresh_records(const query_input& input, std::size_t parts, bool keep_bounds) {
    // The records in the kept order with this call's rows; every rectangle's
    // bounds must lie inside its widened bounds. A row that fails its check
    // makes this false too: the full query names it.
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const bool check_a = !input.a_checked;
    const bool check_b = !input.b_checked;
    std::vector<unsigned char> fits(parts, 1);
    const bool stream = n_ * sizeof(record) > store_bytes_from_dram;
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        constexpr std::size_t ahead = random_rows_ahead;
        bounds_run b;
        bool ok = true;
        // Plain locals: the record stores may alias anything the loop reads.
        const query_input in = input;
        const std::uint32_t* const order = order_.data();
        record* const records = records_.data();
        // Records read from DRAM by the test are written past the cache: a
        // run is staged here, its bounds computed from the stage, and then
        // streamed out, so no old record is read in before it is overwritten.
        alignas(64) record stage[bounds_run::size];
        for (std::size_t run_begin = begin; run_begin < end && ok; run_begin += bounds_run::size) {
            const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
            record* const into = stream ? stage : records + run_begin;
            for (std::size_t k = run_begin; k < run_end; ++k) {
                if (k + ahead < end) {
                    fetch_into_l2(record_at(in, order[k + ahead]));
                }
                const std::uint32_t id = order[k];
                if (id < in.a_count ? check_a : check_b) {
                    ok &= valid_row(in.kind, record_at(in, id));
                }
                copy_row(in, id, into[k - run_begin].v);
            }
            bounds(kind_, into[0].v, run_end - run_begin, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
            if (stream) {
                stream_records(stage, run_end - run_begin, records + run_begin);
            }
            for (std::size_t k = run_begin; k < run_end; ++k) {
                const std::size_t r = k - run_begin;
                const unsigned inside = static_cast<unsigned>(b.lo_x[r] >= in_lo_x_[k]) &
                                        static_cast<unsigned>(b.lo_y[r] >= in_lo_y_[k]) &
                                        static_cast<unsigned>(b.hi_x[r] <= in_hi_x_[k]) &
                                        static_cast<unsigned>(b.hi_y[r] <= in_hi_y_[k]);
                ok &= inside != 0;
            }
            if (keep_bounds) {
                for (std::size_t k = run_begin; k < run_end; ++k) {
                    kept_.now[k] = signed_bounds_of(b, k - run_begin);
                }
            }
        }
        if (stream) {
            finish_streams();
        }
        fits[share] = ok ? 1 : 0;
    });
    return std::find(fits.begin(), fits.end(), 0) == fits.end();
}

void pair_search::keep_candidates(std::size_t parts) {
    // The parts' candidates one after the other, in the sweep's order, and
    // each one's pair in the caller's indices tagged with its position.
    const auto start = clock_type::now();
    std::vector<std::size_t> offsets(parts + 1, 0);
    for (std::size_t i = 0; i < parts; ++i) {
        offsets[i + 1] = offsets[i] + parts_[i].keep.captured.size();
    }
    kept_.pairs.resize(offsets[parts]);
    std::vector<pair_source<tagged_pair>> sources;
    run_parts(parts, [&](std::size_t share) {
        part& p = parts_[share];
        std::copy(p.keep.captured.begin(), p.keep.captured.end(),
                  kept_.pairs.begin() + static_cast<std::ptrdiff_t>(offsets[share]));
        p.keep.tagged.resize(p.keep.captured.size());
        for (std::size_t i = 0; i < p.keep.captured.size(); ++i) {
            const pair_index caller = caller_pair(p.keep.captured[i]);
            p.keep.tagged[i] = tagged_pair{caller.a, caller.b, static_cast<std::uint32_t>(offsets[share] + i)};
        }
        p.keep.captured.clear();
    });
    for (std::size_t i = 0; i < parts; ++i) {
        sources.push_back({{parts_[i].keep.tagged.data(), parts_[i].keep.tagged.size()}});
    }
    if (kept_.tag_scratch.size() < parts) {
        kept_.tag_scratch.resize(parts);
    }
    sort_pairs(sources, self_ ? n_ : a_count_, kept_.by_caller, kept_.tag_scratch);
    for (std::size_t i = 0; i < parts; ++i) {
        parts_[i].keep.tagged.clear();
    }
    stats_.kept_candidates = kept_.pairs.size();
    kept_.answer_parts = 0;
    stats_.output_seconds += seconds_since(start);
}

void pair_search::mark_answer_shares(std::size_t parts) {
    if (kept_.answer_parts == parts) {
        return;
    }
    const std::size_t words = kept_.verdicts.size();  // test_kept sized it for kept_.pairs
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
            marks[kept[j].tag / 64] |= std::uint64_t{1} << (kept[j].tag % 64);
        }
    });
    kept_.answer_parts = parts;
}

void pair_search::test_kept(std::size_t parts, bool unfiltered) {
    // The kept candidates whose bounds overlap now, by the sweep's own test,
    // are the candidates a sweep would find; the method decides them, or,
    // `unfiltered`, every kept candidate.
    const auto start = clock_type::now();
    if (parts_.size() < parts) {
        parts_.resize(parts);
    }
    kept_.verdicts.resize((kept_.pairs.size() + 63) / 64);
    mark_answer_shares(parts);
    const std::size_t words = kept_.verdicts.size();
    const signed_bounds* const now = kept_.now.data();
    run_parts(parts, [&](std::size_t share) {
        part& p = parts_[share];
        p.keep.colliding_in_share.assign(parts, 0);
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
            const auto keep_bits = [&] {
                const std::size_t n = last - first;
                for (std::size_t w = 0; 64 * w < n; ++w) {
                    const std::size_t in_word = std::min<std::size_t>(64, n - 64 * w);
                    const std::size_t word = first / 64 + w;
                    const std::uint64_t bits = verdict_word(verdicts + 64 * w, in_word);
                    verdict_words[word] = bits;
                    for (std::size_t s = 1; s < parts; ++s) {
                        in_share[s] += bits_set(bits & marks[(s - 1) * words + word]);
                    }
                }
            };
            if (unfiltered) {
                test_pairs(p, kept + first, last - first, verdicts);
                p.keep.colliding += count_colliding(verdicts, last - first);
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
            p.keep.colliding += count_colliding(tested, count);
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
