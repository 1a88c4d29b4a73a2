#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "support/bit_width.hpp"
#include "support/fetch_ahead.hpp"
#include "store/finite_check.hpp"
#include "methods/method_check.hpp"
#include "sort/pair_sort.hpp"
#include "store/pose_record.hpp"
#include "sort/radix_sort.hpp"
#include "dispatch/strip_view.hpp"
#include "support/thread_pool.hpp"

#include <obbsat/error.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/bounds.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>

namespace obbsat::detail {

namespace {

/// Strips are this many mean bounds heights tall (measured: see docs/performance.md).
constexpr double strip_factor = 2.0;

/// Candidates handed to the method's kernel at once.
constexpr std::size_t candidate_block = 2048;
static_assert(candidate_block <= pair_blocks::block_pairs, "a block of candidates fits in a block of found pairs");

/// A query that widens its bounds keeps at most this many times the
/// candidates of the last query, plus one per rectangle; a scene whose
/// widened bounds would give more is answered as a plain query.
constexpr std::size_t kept_budget_factor = 4;

/// Found pairs handed to a streaming sink at once.
constexpr std::size_t emit_block = 4096;

/// Below this many rectangles per part, a second core costs more than it saves.
constexpr std::size_t min_boxes_per_part = 16384;

using clock_type = std::chrono::steady_clock;

double seconds_since(clock_type::time_point start) {
    return std::chrono::duration<double>(clock_type::now() - start).count();
}

std::size_t parts_for(std::size_t boxes, unsigned threads) {
    std::size_t wanted = threads;
    if (wanted == 0) {
        wanted = std::max(1u, std::thread::hardware_concurrency());
    }
    return std::max<std::size_t>(1, std::min(wanted, boxes / min_boxes_per_part));
}

/// Runs task(part) for every part, on the shared pool when there are several.
template <class Task>
void run_parts(std::size_t parts, const Task& task) {
    if (parts <= 1) {
        task(std::size_t{0});
        return;
    }
    thread_pool::shared().run(parts, [&](std::size_t share) { task(share); });
}

/// [begin, end) of part `part` of `parts` over n items.
std::pair<std::size_t, std::size_t> share_of(std::size_t n, std::size_t part, std::size_t parts) {
    return {n * part / parts, n * (part + 1) / parts};
}

const float* record_at(const query_input& input, std::size_t id) {
    return id < input.a_count ? input.a + input.a_stride * id : input.b + input.b_stride * (id - input.a_count);
}

std::size_t stride_of(const query_input& input, std::size_t id) {
    return id < input.a_count ? input.a_stride : input.b_stride;
}

/// True iff the values of one row are a valid rectangle of its kind (finite_check.hpp).
bool valid_row(store_kind kind, const float* v) {
    return kind == store_kind::poses ? valid_pose_row(v) : all_finite(v, 8);
}

/// Throws the store's own message for row `id` of the query, which valid_row
/// refused: "pose 7: ..." or "rectangle 7: ...", with "a: " or "b: " in front
/// in a query across two sets.
[[noreturn]] void refuse_row(const query_input& input, std::size_t id) {
    const bool second = id >= input.a_count;
    const std::size_t index = second ? id - input.a_count : id;
    const float* v = record_at(input, id);
    try {
        if (input.kind == store_kind::poses) {
            require_valid_pose(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}, index);
        } else {
            require_finite(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}, index);
        }
    } catch (const invalid_input& e) {
        if (input.b == nullptr) {
            throw;
        }
        throw invalid_input(std::string(second ? "b: " : "a: ") + e.what());
    }
    throw std::logic_error("obbsat: a row refused by the scene query passed its store's check");
}

ref::box_bounds bounds_of_record(store_kind kind, const float* v) {
    if (kind == store_kind::poses) {
        return ref::bounds_of(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}});
    }
    return ref::bounds_of(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
}

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

/// Copies row `id` of the query into `out` (a pose row's two last floats zero).
void copy_row(const query_input& input, std::size_t id, float* out) {
    const float* row = record_at(input, id);
    if (stride_of(input, id) == 8) {
        std::memcpy(out, row, 8 * sizeof(float));
    } else {
        widen_pose_row(out, row);
    }
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

/// [begin, end) of part `part` of `parts` over n items, every boundary but n
/// on a multiple of 64: the parts then write disjoint words of a bit set.
std::pair<std::size_t, std::size_t> word_share_of(std::size_t n, std::size_t part, std::size_t parts) {
    const auto boundary = [&](std::size_t k) { return k == parts ? n : (n * k / parts) & ~std::size_t{63}; };
    return {boundary(part), boundary(part + 1)};
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

double clamp_finite(float x) {
    return static_cast<double>(std::min(std::max(x, -FLT_MAX), FLT_MAX));
}

}  // namespace

pair_search::pair_search(const collide_options& options) : options_(options) {}

void pair_search::widen(bounds_run& b, std::size_t count) const {
    if (!keep_ || margin_ == 0.0f) {
        return;
    }
    // Each box by a share of its larger extent or of the scene's typical
    // extent, whichever is larger, so that a few huge boxes widen only
    // themselves and the smallest still get room to move. Rounding is
    // monotone, so lo - m <= lo and hi + m >= hi: the widened bounds contain
    // the bounds. An extent is never NaN (lo <= hi, at worst -inf and +inf),
    // so neither is m.
    for (std::size_t i = 0; i < count; ++i) {
        const float m = margin_ * std::max(std::max(b.hi_x[i] - b.lo_x[i], b.hi_y[i] - b.lo_y[i]), typical_extent_);
        b.lo_x[i] -= m;
        b.lo_y[i] -= m;
        b.hi_x[i] += m;
        b.hi_y[i] += m;
    }
}

void pair_search::input_bounds(const query_input& input, std::size_t begin, std::size_t end, bounds_run& out) const {
    const bounds_fn kernel = kernels_for(ran_).bounds;
    std::size_t i = begin;
    while (i < end) {
        // One set at a time: the rows of a and of b may have different strides.
        const bool in_a = i < input.a_count;
        const std::size_t stop = in_a ? std::min(end, input.a_count) : end;
        const std::size_t o = i - begin;
        if ((in_a ? input.a_stride : input.b_stride) == 8) {
            kernel(kind_, record_at(input, i), stop - i, out.lo_x + o, out.lo_y + o, out.hi_x + o, out.hi_y + o);
        } else {
            for (std::size_t k = i; k < stop; ++k) {
                const ref::box_bounds b = bounds_of_record(kind_, record_at(input, k));
                out.lo_x[k - begin] = b.lo_x;
                out.lo_y[k - begin] = b.lo_y;
                out.hi_x[k - begin] = b.hi_x;
                out.hi_y[k - begin] = b.hi_y;
            }
        }
        i = stop;
    }
}

void pair_search::measure_extent(const query_input& input, std::size_t parts, bool with_keys) {
    if (with_keys) {
        key_by_id_.resize(n_);
    }
    struct partial {
        double x_low = std::numeric_limits<double>::infinity();
        double x_high = -std::numeric_limits<double>::infinity();
        double y_low = std::numeric_limits<double>::infinity();
        double y_high = -std::numeric_limits<double>::infinity();
        double height_sum = 0;
        std::size_t first_bad = std::numeric_limits<std::size_t>::max();
        std::array<std::uint32_t, 256> exponents{};  ///< of the boxes' larger extents, before widening
    };
    std::vector<partial> partials(parts);
    // Rows the caller's memory holds are checked here, as they are read; a
    // row that fails takes no part in anything that follows.
    const bool check_a = !input.a_checked;
    const bool check_b = !input.b_checked;
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        float x_low = FLT_MAX, x_high = -FLT_MAX, y_low = FLT_MAX, y_high = -FLT_MAX;
        float height_sum = 0;
        double total = 0;
        std::size_t first_bad = std::numeric_limits<std::size_t>::max();
        std::array<std::uint32_t, 256>& exponents = partials[share].exponents;
        // Heights are summed in float over runs and in double across them.
        bounds_run b;
        std::uint32_t extent_exponent[bounds_run::size];
        for (std::size_t run_begin = begin; run_begin < end; run_begin += bounds_run::size) {
            const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
            input_bounds(input, run_begin, run_end, b);
            for (std::size_t r = 0; r < run_end - run_begin; ++r) {
                const float extent = std::max(b.hi_x[r] - b.lo_x[r], b.hi_y[r] - b.lo_y[r]);
                std::uint32_t bits;
                std::memcpy(&bits, &extent, sizeof bits);
                extent_exponent[r] = (bits >> 23) & 0xffu;
            }
            widen(b, run_end - run_begin);
            for (std::size_t i = run_begin; i < run_end; ++i) {
                // A row that fails its check has bounds of no meaning: it takes no part.
                if ((i < a_count_ ? check_a : check_b) && !valid_row(kind_, record_at(input, i))) {
                    first_bad = std::min(first_bad, i);
                    continue;
                }
                const std::size_t r = i - run_begin;
                ++exponents[extent_exponent[r]];
                if (with_keys) {
                    key_by_id_[i] = grid_.key_of(b.lo_x[r], b.lo_y[r]);
                }
                x_low = std::min(x_low, b.lo_x[r]);
                x_high = std::max(x_high, b.hi_x[r]);
                y_low = std::min(y_low, b.lo_y[r]);
                y_high = std::max(y_high, b.hi_y[r]);
                height_sum += std::min(b.hi_y[r] - b.lo_y[r], FLT_MAX / bounds_run::size);
            }
            total += static_cast<double>(height_sum);
            height_sum = 0;
        }
        partial& p = partials[share];
        p.x_low = clamp_finite(x_low);
        p.x_high = clamp_finite(x_high);
        p.y_low = clamp_finite(y_low);
        p.y_high = clamp_finite(y_high);
        p.height_sum = total + static_cast<double>(height_sum);
        p.first_bad = first_bad;
    });
    for (const partial& p : partials) {
        if (p.first_bad != std::numeric_limits<std::size_t>::max()) {
            refuse_row(input, p.first_bad);  // parts are in order: the first bad row of all
        }
    }
    partial all;
    for (const partial& p : partials) {
        all.x_low = std::min(all.x_low, p.x_low);
        all.x_high = std::max(all.x_high, p.x_high);
        all.y_low = std::min(all.y_low, p.y_low);
        all.y_high = std::max(all.y_high, p.y_high);
        all.height_sum += p.height_sum;
    }
    extent_ = bounds_extent{all.x_low, all.x_high, all.y_low, all.y_high,
                            all.height_sum / static_cast<double>(n_)};
    // The median of the boxes' larger extents, to the power of two below it:
    // a histogram of float exponents, robust to a few huge or tiny boxes.
    // Exponent 0 holds zero and subnormal extents, 255 infinite ones: no scale.
    std::size_t seen = 0;
    int median = 0;
    for (int e = 0; e < 256; ++e) {
        for (const partial& p : partials) {
            seen += p.exponents[static_cast<std::size_t>(e)];
        }
        if (2 * seen > n_) {
            median = e;
            break;
        }
    }
    measured_typical_extent_ = median > 0 && median < 255 ? std::ldexp(1.0f, median - 127) : 0.0f;
}

bool pair_search::same_scene_as_last() const {
    return have_order_ && ordered_n_ == n_ && ordered_a_count_ == a_count_ && ordered_kind_ == kind_ &&
           ordered_self_ == self_;
}

void pair_search::order_boxes(const query_input& input, std::size_t parts) {
    // measure_extent computed the keys on the last grid when there was one.
    const bool keep_grid = same_scene_as_last() && grid_still_fits(grid_, extent_);
    if (!keep_grid) {
        grid_ = grid_for(extent_, n_, strip_factor);
    }
    keys_.resize(n_);
    order_.resize(n_);
    stats_.reused_order = keep_grid && repair_order(parts);
    if (!stats_.reused_order) {
        run_parts(parts, [&](std::size_t share) {
            const auto [begin, end] = share_of(n_, share, parts);
            bounds_run b;
            for (std::size_t run_begin = begin; run_begin < end; run_begin += bounds_run::size) {
                const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
                input_bounds(input, run_begin, run_end, b);
                widen(b, run_end - run_begin);
                for (std::size_t i = run_begin; i < run_end; ++i) {
                    keys_[i] = grid_.key_of(b.lo_x[i - run_begin], b.lo_y[i - run_begin]);
                    order_[i] = static_cast<std::uint32_t>(i);
                }
            }
        });
        radix_sort(keys_.data(), order_.data(), n_, grid_.key_bits(), packed_, spare_, parts);
    }
    have_order_ = true;
    ordered_n_ = n_;
    ordered_a_count_ = a_count_;
    ordered_kind_ = kind_;
    ordered_self_ = self_;
}

bool pair_search::repair_order(std::size_t parts) {
    // The last order with this query's keys: nearly sorted when the
    // rectangles moved a little, but for those that changed strips, each of
    // which an insertion sort would carry across about half its new strip.
    // So the rectangles that stayed in their strips keep the last order and
    // are repaired there, strip by strip, the strips split between the
    // threads; those that changed strips are sorted apart; the two are then
    // merged. keys_ still holds the last query's keys, in its order.
    const unsigned q_bits = grid_.q_bits;
    changed_strip_.resize(n_);
    std::vector<std::size_t> changed_before(parts + 1, 0);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        std::size_t changed = 0;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t key = key_by_id_[order_[k]];
            const bool moved = (key >> q_bits) != (keys_[k] >> q_bits);
            changed_strip_[k] = moved ? 1 : 0;
            changed += moved ? 1 : 0;
            keys_[k] = key;
        }
        changed_before[share + 1] = changed;
    });
    std::partial_sum(changed_before.begin(), changed_before.end(), changed_before.begin());
    const std::size_t changed = changed_before[parts];
    const std::size_t stayed = n_ - changed;
    stay_keys_.resize(stayed);
    stay_ids_.resize(stayed);
    moved_keys_.resize(changed);
    moved_ids_.resize(changed);
    // The rectangles that stayed are in the order of their strips already,
    // as each share checks (and the shares' ends against each other): the
    // strips are found by position below.
    std::vector<std::uint32_t> first_strip(parts, 0), last_strip(parts, 0);
    std::vector<unsigned char> in_strip_order(parts, 1);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        std::size_t m = changed_before[share];
        std::size_t s = begin - m;
        const std::size_t share_first = s;
        std::uint32_t last = 0;
        unsigned ordered = 1;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t key = keys_[k];
            if (changed_strip_[k] != 0) {
                moved_keys_[m] = key;
                moved_ids_[m] = order_[k];
                ++m;
            } else {
                ordered &= (key >> q_bits) >= last ? 1u : 0u;
                last = key >> q_bits;
                stay_keys_[s] = key;
                stay_ids_[s] = order_[k];
                ++s;
            }
        }
        first_strip[share] = s > share_first ? stay_keys_[share_first] >> q_bits : 0;
        last_strip[share] = last;
        in_strip_order[share] = static_cast<unsigned char>(ordered);
    });
    std::uint32_t last_so_far = 0;
    for (std::size_t share = 0; share < parts; ++share) {
        const auto [begin, end] = share_of(n_, share, parts);
        const bool stayers = end - begin > changed_before[share + 1] - changed_before[share];
        if (in_strip_order[share] == 0 || (stayers && first_strip[share] < last_so_far)) {
            return false;
        }
        last_so_far = stayers ? last_strip[share] : last_so_far;
    }
    std::vector<std::uint32_t> strip_begin(grid_.strips + 1);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(stayed, share, parts);
        bucket_starts(stay_keys_.data(), stayed, q_bits, grid_.strips, begin, end, strip_begin.data());
    });
    std::vector<unsigned char> repaired(parts, 1);
    run_parts(parts, [&](std::size_t share) {
        const std::size_t first = grid_.strips * share / parts;
        const std::size_t last = grid_.strips * (share + 1) / parts;
        const std::size_t begin = strip_begin[first];
        const std::size_t end = strip_begin[last];
        std::size_t budget = 16 * (end - begin);
        for (std::size_t s = first; s < last && repaired[share] != 0; ++s) {
            const std::size_t b = strip_begin[s];
            const std::size_t count = strip_begin[s + 1] - b;
            std::size_t moved = 0;
            if (!repair_sort(stay_keys_.data() + b, stay_ids_.data() + b, count, budget, &moved)) {
                repaired[share] = 0;
            }
            budget -= std::min(budget, moved);
        }
    });
    if (std::find(repaired.begin(), repaired.end(), 0) != repaired.end()) {
        return false;
    }
    radix_sort(moved_keys_.data(), moved_ids_.data(), changed, grid_.key_bits(), packed_, spare_, parts);
    merge_by_key(stay_keys_.data(), stay_ids_.data(), stayed, moved_keys_.data(), moved_ids_.data(), changed,
                 keys_.data(), order_.data(), parts);
    return true;
}

void pair_search::copy_records(const query_input& input, std::size_t parts) {
    records_.resize(n_);
    in_lo_x_.resize(n_);
    in_lo_y_.resize(n_);
    in_hi_x_.resize(n_);
    in_hi_y_.resize(n_);
    q_lo_.resize(n_);
    q_hi_.resize(n_);
    strip_hi_.resize(n_);
    side_.resize(n_);
    if (keep_) {
        now_.resize(n_);
    }
    const bounds_fn bounds = kernels_for(ran_).bounds;
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        constexpr std::size_t ahead = random_rows_ahead;
        bounds_run b;
        for (std::size_t run_begin = begin; run_begin < end; run_begin += bounds_run::size) {
            const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
            for (std::size_t k = run_begin; k < run_end; ++k) {
                if (k + ahead < end) {
                    fetch_into_l2(record_at(input, order_[k + ahead]));
                }
                const std::uint32_t id = order_[k];
                copy_row(input, id, records_[k].v);
                side_[k] = id >= a_count_ && !self_ ? 1 : 0;
            }
            // The same function on the same floats as the extent pass: the bounds of step 1.
            bounds(kind_, records_[run_begin].v, run_end - run_begin, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
            if (keep_) {
                // The bounds themselves for the kept candidates' test, the widened ones for the sweep.
                for (std::size_t k = run_begin; k < run_end; ++k) {
                    now_[k] = signed_bounds_of(b, k - run_begin);
                }
                widen(b, run_end - run_begin);
            }
            for (std::size_t k = run_begin; k < run_end; ++k) {
                const std::size_t r = k - run_begin;
                in_lo_x_[k] = b.lo_x[r];
                in_lo_y_[k] = b.lo_y[r];
                in_hi_x_[k] = b.hi_x[r];
                in_hi_y_[k] = b.hi_y[r];
                q_lo_[k] = grid_.q_of(b.lo_x[r]);
                q_hi_[k] = grid_.q_of(b.hi_x[r]);
                strip_hi_[k] = grid_.strip_of(b.hi_y[r]);
            }
        }
    });
}

void pair_search::collect_visits(std::size_t parts) {
    // A rectangle taller than its strip visits each strip above its lowest
    // up to its highest; the visits are wanted sorted by key, ties by
    // rectangle. The rectangles are in key order, so the visits to the strip
    // just above each one's lowest ("near" visits, most of them) come out in
    // that order already; only the others ("far" visits, of rectangles taller
    // than a strip) are radix sorted, and then merged in. Each share counts
    // its visits, then writes them after the shares before it.
    const std::uint32_t strips = grid_.strips;
    const unsigned q_bits = grid_.q_bits;
    std::vector<std::size_t> first_near(parts + 1, 0), first_far(parts + 1, 0);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        std::size_t near = 0, far = 0;
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t hops = strip_hi_[k] - (keys_[k] >> q_bits);
            const std::uint32_t is_near = hops != 0 ? 1 : 0;
            near += is_near;
            far += hops - is_near;
        }
        first_near[share + 1] = near;
        first_far[share + 1] = far;
    });
    for (std::size_t share = 0; share < parts; ++share) {
        first_near[share + 1] += first_near[share];
        first_far[share + 1] += first_far[share];
    }
    const std::size_t far_count = first_far[parts];
    const std::size_t near_count = first_near[parts];
    const std::size_t visits = far_count + near_count;
    // One more entry after the last visit, for the sweep's merge to read.
    // With no far visits the near ones are the visits; otherwise they go to
    // arrays of their own, from which the merge reads while it writes.
    visit_keys_.resize(visits + 1);
    visit_ids_.resize(visits + 1);
    far_keys_.resize(far_count);
    far_ids_.resize(far_count);
    if (far_count > 0) {
        near_keys_.resize(near_count);
        near_ids_.resize(near_count);
    }
    std::uint32_t* const near_keys = far_count > 0 ? near_keys_.data() : visit_keys_.data();
    std::uint32_t* const near_ids = far_count > 0 ? near_ids_.data() : visit_ids_.data();
    own_begin_.resize(strips + 1);
    std::vector<unsigned char> near_sorted(parts, 1);
    run_parts(parts, [&](std::size_t share) {
        const auto [begin, end] = share_of(n_, share, parts);
        bucket_starts(keys_.data(), n_, q_bits, strips, begin, end, own_begin_.data());
        std::size_t v = first_near[share];
        std::size_t f = first_far[share];
        std::uint32_t last_key = 0;
        unsigned sorted = 1;
        // Whether a rectangle visits at all is as random as the scene: a
        // rectangle that does not writes its would-be visit to `unused`.
        std::uint32_t unused[2];
        for (std::size_t k = begin; k < end; ++k) {
            const std::uint32_t low = keys_[k] >> q_bits;
            const std::uint32_t high = strip_hi_[k];
            const bool is_near = high != low;
            const std::uint32_t key = ((low + 1) << q_bits) | q_lo_[k];
            sorted &= (key >= last_key) | !is_near ? 1u : 0u;
            last_key = is_near ? key : last_key;
            *(is_near ? near_keys + v : unused) = key;
            *(is_near ? near_ids + v : unused + 1) = static_cast<std::uint32_t>(k);
            v += is_near ? 1 : 0;
            for (std::uint32_t s = low + 2; s <= high; ++s) {
                far_keys_[f] = (s << q_bits) | q_lo_[k];
                far_ids_[f] = static_cast<std::uint32_t>(k);
                ++f;
            }
        }
        near_sorted[share] = static_cast<unsigned char>(sorted);
    });
    // The near visits are in key order when each rectangle's key and its
    // quantized lo_x agree, as they are computed from the same bounds; if
    // they ever did not, every visit is sorted, which gives the same order.
    bool merge = std::find(near_sorted.begin(), near_sorted.end(), 0) == near_sorted.end();
    for (std::size_t share = 1; share < parts && merge; ++share) {
        const std::size_t at = first_near[share];
        merge = at == 0 || at == near_count || near_keys[at - 1] <= near_keys[at];
    }
    if (merge) {
        if (far_count > 0) {
            radix_sort(far_keys_.data(), far_ids_.data(), far_count, grid_.key_bits(), packed_, spare_, parts);
            merge_by_key(near_keys_.data(), near_ids_.data(), near_count, far_keys_.data(), far_ids_.data(), far_count,
                         visit_keys_.data(), visit_ids_.data(), parts);
        }
    } else {
        if (far_count > 0) {
            std::copy(far_keys_.begin(), far_keys_.end(), visit_keys_.begin());
            std::copy(far_ids_.begin(), far_ids_.end(), visit_ids_.begin());
            std::copy(near_keys_.begin(), near_keys_.end(), visit_keys_.begin() + static_cast<std::ptrdiff_t>(far_count));
            std::copy(near_ids_.begin(), near_ids_.end(), visit_ids_.begin() + static_cast<std::ptrdiff_t>(far_count));
        }
        radix_sort(visit_keys_.data(), visit_ids_.data(), visits, grid_.key_bits(), packed_, spare_, parts);
    }
    visit_keys_[visits] = 0;
    visit_ids_[visits] = 0;
    visit_begin_.assign(strips + 1, 0);
    if (visits > 0) {
        run_parts(parts, [&](std::size_t share) {
            const auto [begin, end] = share_of(visits, share, parts);
            bucket_starts(visit_keys_.data(), visits, q_bits, strips, begin, end, visit_begin_.data());
        });
    }
    stats_.strips = strips;
    stats_.visits = visits;
}

void pair_search::test_pairs(part& p, const pair_index* pairs, std::size_t count, std::uint8_t* verdicts) const {
    const kernel_table& table = kernels_for(ran_);
    const auto kernel_start = clock_type::now();
    if (kind_ == store_kind::poses) {
        p.slow_path += table.on_poses(options_.test).indexed_near(records_.data()->v, pairs, count, verdicts);
    } else {
        p.slow_path += table.of(options_.test)
                           .indexed_records_near(reinterpret_cast<const rect*>(records_.data()), pairs, count,
                                                 verdicts);
    }
    p.kernel_seconds += seconds_since(kernel_start);
    p.tested += count;
}

void pair_search::test_candidates(part& p, std::size_t count) const {
    test_pairs(p, p.candidates.data(), count, p.verdicts.data());
}

void pair_search::flush_candidates(part& p) const {
    const std::size_t count = p.candidate_count;
    if (count == 0) {
        return;
    }
    // Methods need not be symmetric (local works in the first rectangle's
    // frame; sat4 on a degenerate quad may differ), so each candidate is put
    // in the order the caller's pair has: within one store the smaller index
    // first, across two the first store's rectangle first.
    const auto offset = static_cast<std::uint32_t>(a_count_);
    pair_index* const candidates = p.candidates.data();
    // Which way round is as random as the caller's indices: a mask, not a
    // branch that would mispredict on every other candidate.
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t first = candidates[i].a;
        const std::uint32_t second = candidates[i].b;
        const std::uint32_t x = order_[first];
        const std::uint32_t y = order_[second];
        const bool swap = self_ ? x > y : x >= offset;
        const std::uint32_t flip = (first ^ second) & (0u - static_cast<std::uint32_t>(swap));
        candidates[i].a = first ^ flip;
        candidates[i].b = second ^ flip;
    }
    if (keep_) {
        // Past the budget of all parts a part keeps nothing more: the call
        // then answers as a plain query (collect). Whether any part sees the
        // budget passed depends only on the sum of the parts' candidates.
        if (captured_all_.fetch_add(count, std::memory_order_relaxed) + count <= capture_budget_) {
            p.captured.insert(p.captured.end(), candidates, candidates + count);
        } else {
            p.over_budget = true;
        }
        p.candidate_count = 0;
        return;
    }
    test_candidates(p, count);
    pair_index* out = p.found.room(count);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i) {
        out[kept] = caller_pair(candidates[i]);
        kept += p.verdicts[i] != 0 ? 1u : 0u;
    }
    p.found.add(kept);
    p.candidate_count = 0;
}

void pair_search::sweep_strip(std::uint32_t strip, part& p) const {
    // Merge the rectangles starting in this strip with its visitors, by
    // quantized lo_x (a rectangle before a visitor on equal keys).
    const std::size_t own_begin = own_begin_[strip];
    const std::size_t own_end = own_begin_[strip + 1];
    const std::size_t visit_begin = visit_begin_[strip];
    const std::size_t visit_end = visit_begin_[strip + 1];
    const std::size_t m = (own_end - own_begin) + (visit_end - visit_begin);
    if (m < 2) {
        return;
    }
    const std::size_t room = m + strip_padding;
    if (p.q_lo.size() < room) {
        p.id.resize(room);
        for (auto* v : {&p.q_lo, &p.q_hi, &p.starts, &p.store, &p.lo_x, &p.lo_y, &p.hi_x, &p.hi_y}) {
            v->resize(room);
        }
    }
    float* const q_lo = p.q_lo.data();
    float* const q_hi = p.q_hi.data();
    std::int32_t* const ids = p.id.data();
    float* const starts = p.starts.data();
    float* const store = p.store.data();
    float* const lo_x = p.lo_x.data();
    float* const lo_y = p.lo_y.data();
    float* const hi_x = p.hi_x.data();
    float* const hi_y = p.hi_y.data();
    const std::uint32_t* const visit_keys = visit_keys_.data();
    const std::uint32_t* const visit_ids = visit_ids_.data();
    const std::uint32_t q_mask = grid_.q_max;
    // Which side comes next is as random as the scene, so the merge selects
    // without branching: a side that has run out reads as the largest key,
    // and reads stay in bounds (the last rectangle, the visit after the last).
    constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    const std::size_t last = n_ - 1;
    std::size_t o = own_begin;
    std::size_t v = visit_begin;
    for (std::size_t e = 0; e < m; ++e) {
        const std::uint32_t own_q = o < own_end ? q_lo_[std::min(o, last)] : none;
        const std::uint32_t visit_q = v < visit_end ? (visit_keys[v] & q_mask) : none;
        const std::size_t take_own = own_q <= visit_q ? 1u : 0u;
        const std::size_t own_mask = 0u - take_own;
        const std::size_t k = (o & own_mask) | (visit_ids[v] & ~own_mask);
        o += take_own;
        v += 1u - take_own;
        q_lo[e] = static_cast<float>(q_lo_[k]);
        q_hi[e] = static_cast<float>(q_hi_[k]);
        ids[e] = static_cast<std::int32_t>(k);
        starts[e] = static_cast<float>(take_own);
        store[e] = static_cast<float>(side_[k]);
        lo_x[e] = in_lo_x_[k];
        lo_y[e] = in_lo_y_[k];
        hi_x[e] = in_hi_x_[k];
        hi_y[e] = in_hi_y_[k];
    }
    for (std::size_t e = m; e < room; ++e) {
        q_lo[e] = std::numeric_limits<float>::infinity();
        q_hi[e] = 0;
        ids[e] = 0;
        starts[e] = -1;  // never at least an entry's starts_needed (0 or 1): never taken
        store[e] = 0;
        lo_x[e] = std::numeric_limits<float>::infinity();
        lo_y[e] = 0;
        hi_x[e] = 0;
        hi_y[e] = 0;
    }
    const strip_view view{q_lo, q_hi, ids, starts, store, lo_x, lo_y, hi_x, hi_y, m, !self_};
    const strip_sweep_fn sweep_kernel = kernels_for(ran_).strip_sweep;
    sweep_cursor cursor;
    while (cursor.e + 1 < m) {
        const std::size_t before = p.candidate_count;
        p.candidate_count +=
            sweep_kernel(view, cursor, p.candidates.data() + before, candidate_block - before);
        if (cursor.e + 1 < m) {
            flush_candidates(p);
        }
    }
}

void pair_search::sweep(std::size_t parts, const pair_chunk_sink* emit) {
    // Strips split so that each part has about the same number of entries.
    const std::uint32_t strips = grid_.strips;
    const std::size_t entries = n_ + stats_.visits;
    if (parts_.size() < parts) {
        parts_.resize(parts);
    }
    std::uint32_t s = 0;
    for (std::size_t i = 0; i < parts; ++i) {
        part& p = parts_[i];
        p.first_strip = s;
        const std::size_t target = entries * (i + 1) / parts;
        while (s < strips && (i + 1 == parts || own_begin_[s] + visit_begin_[s] < target)) {
            ++s;
        }
        p.end_strip = s;
        if (p.candidates.size() < candidate_block) {
            p.candidates.resize(candidate_block);
            p.verdicts.resize(candidate_block);
        }
        p.candidate_count = 0;
        p.found.clear();
        p.captured.clear();
        p.over_budget = false;
        p.tested = 0;
        p.slow_path = 0;
        p.kernel_seconds = 0;
    }
    capture_budget_ = margin_ > 0.0f ? kept_budget_factor * last_candidates_ + n_ + parts * candidate_block
                                     : std::numeric_limits<std::size_t>::max();
    captured_all_.store(0, std::memory_order_relaxed);
    std::mutex emit_mutex;
    std::vector<std::exception_ptr> failures(parts);
    std::atomic<bool> failed{false};
    run_parts(parts, [&](std::size_t index) {
        part& p = parts_[index];
        try {
            const auto hand_over = [&](bool all) {
                if (emit != nullptr && (all || p.found.size() >= emit_block) && !p.found.empty()) {
                    const std::lock_guard<std::mutex> lock(emit_mutex);
                    if (!failed.load()) {
                        for (const pair_span<pair_index>& span : p.found.spans()) {
                            (*emit)(span.data, span.size);
                        }
                    }
                    p.found.clear();
                }
            };
            for (std::uint32_t strip = p.first_strip; strip < p.end_strip && !failed.load(); ++strip) {
                sweep_strip(strip, p);
                hand_over(false);
            }
            flush_candidates(p);
            hand_over(true);
        } catch (...) {
            failures[index] = std::current_exception();
            failed.store(true);
        }
    });
    for (const std::exception_ptr& failure : failures) {
        if (failure) {
            std::rethrow_exception(failure);
        }
    }
    for (std::size_t i = 0; i < parts; ++i) {
        stats_.candidates += parts_[i].tested;
        stats_.slow_path_pairs += parts_[i].slow_path;
        stats_.kernel_seconds += parts_[i].kernel_seconds;
    }
}

void pair_search::set_query(const query_input& input) {
    detail::require_method_on(options_, input.kind);
    ran_ = resolve_backend(options_.use);
    stats_ = find_pairs_stats{};
    kind_ = input.kind;
    self_ = input.b == nullptr;
    a_count_ = input.a_count;
    n_ = input.a_count + (self_ ? 0 : input.b_count);
    if (n_ > std::numeric_limits<std::uint32_t>::max()) {
        throw invalid_input("a scene query takes at most 4294967295 rectangles, not " + std::to_string(n_));
    }
    stats_.boxes = n_;
}

void pair_search::run(const query_input& input, const pair_chunk_sink& emit) {
    set_query(input);
    used_parts_ = 0;
    for (part& p : parts_) {
        p.found.clear();
    }
    if (n_ < 2 || (!self_ && (input.a_count == 0 || input.b_count == 0))) {
        return;
    }
    const std::size_t parts = parts_for(n_, options_.threads);
    used_parts_ = parts;
    auto start = clock_type::now();
    measure_extent(input, parts, same_scene_as_last());
    order_boxes(input, parts);
    stats_.bounds_seconds = seconds_since(start);
    start = clock_type::now();
    copy_records(input, parts);
    collect_visits(parts);
    stats_.order_seconds = seconds_since(start);
    start = clock_type::now();
    sweep(parts, emit ? &emit : nullptr);
    stats_.sweep_seconds = seconds_since(start);
    if (options_.slow_path_pairs != nullptr) {
        *options_.slow_path_pairs = stats_.slow_path_pairs;
    }
    // The next query widens by this one's typical extent; this one's widening
    // used the last one's throughout.
    typical_extent_ = measured_typical_extent_;
}

void pair_search::sort_found() {
    const auto start = clock_type::now();
    std::vector<pair_source<pair_index>> sources;
    for (std::size_t i = 0; i < used_parts_; ++i) {
        sources.push_back(parts_[i].found.spans());
    }
    const std::size_t parts = std::max<std::size_t>(1, sources.size());
    if (sort_scratch_.size() < parts) {
        sort_scratch_.resize(parts);
    }
    sort_pairs(sources, self_ ? n_ : a_count_, pairs_, sort_scratch_);
    for (part& p : parts_) {
        p.found.clear();
    }
    stats_.pairs = pairs_.size();
    stats_.output_seconds += seconds_since(start);
}

const std::vector<pair_index>& pair_search::collect(const query_input& input) {
    set_query(input);
    const std::size_t parts = parts_for(n_, options_.threads);
    if (kept_ready_ && same_scene_as_last() && n_ >= 2) {
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
            ++kept_calls_;
            stats_.reused_order = true;
            stats_.reused_candidates = true;
            stats_.kept_candidates = kept_.size();
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
    if (kept_ready_ && margin_ > 0.0f) {
        if (kept_calls_ < 4) {
            margin_share_ = std::min(margin_share_ * 2, 1.0 / 2);
        } else if (kept_calls_ > 64) {
            margin_share_ = std::max(margin_share_ / 2, 1.0 / 256);
        }
    }
    kept_ready_ = false;
    kept_calls_ = 0;
    if (!same_scene_as_last()) {
        // The first call on a scene knows no motion yet, and pairs kept from
        // bounds not widened would serve no call after a move: it answers
        // as a plain query, and the next call keeps the pairs of widened bounds.
        return answer_plainly(input);
    }
    margin_ = static_cast<float>(margin_share_);
    keep_ = true;
    try {
        run(input, pair_chunk_sink{});
    } catch (...) {
        keep_ = false;
        throw;
    }
    keep_ = false;
    if (used_parts_ == 0) {
        pairs_.clear();
        return pairs_;
    }
    bool over_budget = false;
    for (std::size_t i = 0; i < used_parts_; ++i) {
        over_budget |= parts_[i].over_budget;
    }
    if (over_budget) {
        // The widened bounds met too many others: this call answers as a
        // plain query, and the next full query widens less.
        for (std::size_t i = 0; i < used_parts_; ++i) {
            std::vector<pair_index>().swap(parts_[i].captured);
        }
        margin_share_ = std::max(margin_share_ / 4, 1.0 / 256);
        return answer_plainly(input);
    }
    keep_candidates(used_parts_);
    kept_ready_ = true;
    test_kept(used_parts_, false);
    last_candidates_ = stats_.candidates;
    answer_from_kept(used_parts_);
    return pairs_;
}

const std::vector<pair_index>& pair_search::answer_plainly(const query_input& input) {
    // keep_ is false: the bounds themselves, not widened (see widen), so the
    // method is asked of the same candidates as in find_pairs.
    run(input, pair_chunk_sink{});
    sort_found();
    last_candidates_ = stats_.candidates;
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
                    now_[k] = signed_bounds_of(b, k - run_begin);
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
        offsets[i + 1] = offsets[i] + parts_[i].captured.size();
    }
    kept_.resize(offsets[parts]);
    std::vector<pair_source<tagged_pair>> sources;
    run_parts(parts, [&](std::size_t share) {
        part& p = parts_[share];
        std::copy(p.captured.begin(), p.captured.end(), kept_.begin() + static_cast<std::ptrdiff_t>(offsets[share]));
        p.tagged.resize(p.captured.size());
        for (std::size_t i = 0; i < p.captured.size(); ++i) {
            const pair_index caller = caller_pair(p.captured[i]);
            p.tagged[i] = tagged_pair{caller.a, caller.b, static_cast<std::uint32_t>(offsets[share] + i)};
        }
        p.captured.clear();
    });
    for (std::size_t i = 0; i < parts; ++i) {
        sources.push_back({{parts_[i].tagged.data(), parts_[i].tagged.size()}});
    }
    if (tag_scratch_.size() < parts) {
        tag_scratch_.resize(parts);
    }
    sort_pairs(sources, self_ ? n_ : a_count_, kept_by_caller_, tag_scratch_);
    for (std::size_t i = 0; i < parts; ++i) {
        parts_[i].tagged.clear();
    }
    stats_.kept_candidates = kept_.size();
    answer_parts_ = 0;
    stats_.output_seconds += seconds_since(start);
}

void pair_search::mark_answer_shares(std::size_t parts) {
    if (answer_parts_ == parts) {
        return;
    }
    const std::size_t words = kept_verdicts_.size();  // test_kept sized it for kept_
    answer_marks_.resize(words * (parts - 1));
    run_parts(parts, [&](std::size_t share) {
        if (share == 0) {
            return;
        }
        std::uint64_t* const marks = answer_marks_.data() + (share - 1) * words;
        std::fill(marks, marks + words, std::uint64_t{0});
        const auto [begin, end] = share_of(kept_by_caller_.size(), share, parts);
        const tagged_pair* const kept = kept_by_caller_.data();
        for (std::size_t j = begin; j < end; ++j) {
            marks[kept[j].tag / 64] |= std::uint64_t{1} << (kept[j].tag % 64);
        }
    });
    answer_parts_ = parts;
}

void pair_search::test_kept(std::size_t parts, bool unfiltered) {
    // The kept candidates whose bounds overlap now, by the sweep's own test,
    // are the candidates a sweep would find; the method decides them, or,
    // `unfiltered`, every kept candidate.
    const auto start = clock_type::now();
    if (parts_.size() < parts) {
        parts_.resize(parts);
    }
    kept_verdicts_.resize((kept_.size() + 63) / 64);
    mark_answer_shares(parts);
    const std::size_t words = kept_verdicts_.size();
    const signed_bounds* const now = now_.data();
    run_parts(parts, [&](std::size_t share) {
        part& p = parts_[share];
        p.colliding_in_share.assign(parts, 0);
        if (p.candidates.size() < candidate_block) {
            p.candidates.resize(candidate_block);
            p.verdicts.resize(candidate_block);
        }
        p.slots.resize(candidate_block);
        p.tested = 0;
        p.colliding = 0;
        p.slow_path = 0;
        p.kernel_seconds = 0;
        const auto [begin, end] = word_share_of(kept_.size(), share, parts);
        // Plain pointers: a byte store may alias anything, and the vectors'
        // own pointers would be reloaded on every candidate.
        const pair_index* const kept = kept_.data();
        std::uint64_t* const verdict_words = kept_verdicts_.data();
        const std::uint64_t* const marks = answer_marks_.data();
        std::size_t* const in_share = p.colliding_in_share.data();
        pair_index* const candidates = p.candidates.data();
        std::uint32_t* const slots = p.slots.data();
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
                p.colliding += count_colliding(verdicts, last - first);
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
            p.colliding += count_colliding(tested, count);
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
        colliding += parts_[i].colliding;
        for (std::size_t share = 1; share < parts; ++share) {
            in_share[share] += parts_[i].colliding_in_share[share];
        }
    }
    in_share[0] = colliding - std::accumulate(in_share.begin() + 1, in_share.end(), std::size_t{0});
    std::vector<std::size_t> offsets(parts + 1, 0);
    std::partial_sum(in_share.begin(), in_share.end(), offsets.begin() + 1);
    pairs_.resize(colliding);
    std::vector<std::size_t> found_in(parts, 0);
    const std::size_t kept_count = kept_by_caller_.size();
    run_parts(parts, [&](std::size_t share) {
        // Named apart, not bound: the step below captures them.
        const std::pair<std::size_t, std::size_t> range = share_of(kept_count, share, parts);
        const std::size_t begin = range.first;
        const std::size_t end = range.second;
        pair_index* const out = pairs_.data() + offsets[share];
        const std::size_t wanted = offsets[share + 1] - offsets[share];
        const std::uint64_t* const verdict_words = kept_verdicts_.data();
        const tagged_pair* const kept = kept_by_caller_.data();
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

std::vector<pair_index> pair_search::collect_once(const query_input& input) {
    run(input, pair_chunk_sink{});
    // The scene's working memory goes before the sorted copy of the pairs is
    // made: the peak is the larger of the two, not their sum.
    decltype(records_)().swap(records_);
    for (auto* v : {&in_lo_x_, &in_lo_y_, &in_hi_x_, &in_hi_y_}) {
        scratch_vector<float>().swap(*v);
    }
    for (auto* v : {&keys_, &order_, &key_by_id_, &q_lo_, &q_hi_, &strip_hi_, &visit_keys_, &visit_ids_, &far_keys_,
                    &far_ids_, &near_keys_, &near_ids_}) {
        scratch_vector<std::uint32_t>().swap(*v);
    }
    radix_buffer().swap(packed_);
    radix_buffer().swap(spare_);
    sort_found();
    return std::move(pairs_);
}

}  // namespace obbsat::detail
