// Step 1 of the scene query (pair_search.hpp): the bounds of every rectangle, their extent, and the rows' check.
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "scene/search_common.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

namespace obbsat::detail {

namespace {

double clamp_finite(float x) {
    return static_cast<double>(std::min(std::max(x, -FLT_MAX), FLT_MAX));
}

}  // namespace

void pair_search::widen(bounds_run& b, std::size_t count) const {
    if (!kept_.keep || kept_.margin == 0.0f) {
        return;
    }
    widen_bounds(b, count, kept_.margin, kept_.typical_extent);
}

void pair_search::widen_bounds(bounds_run& b, std::size_t count, float margin, float typical) {
    // Each box by a share of its larger extent or of the scene's typical
    // extent, whichever is larger, so that a few huge boxes widen only
    // themselves and the smallest still get room to move. Rounding is
    // monotone, so lo - m <= lo and hi + m >= hi: the widened bounds contain
    // the bounds. An extent is never NaN (lo <= hi, at worst -inf and +inf),
    // so neither is m.
    for (std::size_t i = 0; i < count; ++i) {
        const float m = margin * std::max(std::max(b.hi_x[i] - b.lo_x[i], b.hi_y[i] - b.lo_y[i]), typical);
        b.lo_x[i] -= m;
        b.lo_y[i] -= m;
        b.hi_x[i] += m;
        b.hi_y[i] += m;
    }
}

void pair_search::probe_motion(const bounds_run& b, std::size_t first, std::size_t count, bool compare,
                               unsigned& inside) {
    // The margin of the next full query that keeps (widen), on this call's
    // bounds; the comparisons are the refresh's (refresh_records), negated
    // on the upper side, which is exact.
    const float margin = static_cast<float>(kept_.margin_share);
    const float typical = kept_.typical_extent;
    signed_bounds* const last = kept_.last.data() + first;
    unsigned in = 1;
    for (std::size_t r = 0; r < count; ++r) {
        const float lo_x = b.lo_x[r], lo_y = b.lo_y[r], hi_x = b.hi_x[r], hi_y = b.hi_y[r];
        if (compare) {
            const signed_bounds& w = last[r];
            in &= static_cast<unsigned>(lo_x >= w.v[0]) & static_cast<unsigned>(lo_y >= w.v[1]) &
                  static_cast<unsigned>(-hi_x >= w.v[2]) & static_cast<unsigned>(-hi_y >= w.v[3]);
        }
        const float m = margin * std::max(std::max(hi_x - lo_x, hi_y - lo_y), typical);
        last[r] = signed_bounds{{lo_x - m, lo_y - m, -(hi_x + m), -(hi_y + m)}};
    }
    inside &= in;
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
    keys_by_id_fresh_ = with_keys;
    if (with_keys) {
        key_by_id_.resize(n_);
    } else {
        // Each box's lower corner is left in the arrays of the order, as
        // bits (lo_x in keys_, lo_y in order_): order_boxes makes the keys
        // from them once the grid is known, instead of reading every row and
        // computing its bounds a second time. A query that may repair its
        // last order (with_keys) keeps that order's keys in keys_ instead.
        keys_.resize(n_);
        order_.resize(n_);
    }
    struct partial {
        double x_low = std::numeric_limits<double>::infinity();
        double x_high = -std::numeric_limits<double>::infinity();
        double y_low = std::numeric_limits<double>::infinity();
        double y_high = -std::numeric_limits<double>::infinity();
        double height_sum = 0;
        std::size_t first_bad = std::numeric_limits<std::size_t>::max();
        std::array<std::uint32_t, 256> exponents{};  ///< of the boxes' larger extents, before widening
        float tallest = 0;  ///< the largest height of a box, before widening
    };
    // Units taken as they come (work_shares.hpp); each keeps its own partial
    // results, combined in unit order, so none depends on the threads.
    const std::size_t units = units_for(n_, parts, min_boxes_per_unit);
    std::vector<partial> partials(units);
    // Rows the caller's memory holds are checked here, as they are read; a
    // row that fails takes no part in anything that follows.
    const bool check_a = !input.a_checked;
    const bool check_b = !input.b_checked;
    // A paused pair_finder (kept_pairs::paused) probes the motion here, where
    // the bounds are at hand in the caller's order: each box's bounds against
    // the last call's widened ones, which this call's then replace.
    const bool probe = kept_.paused && kept_.probing && !kept_.keep;
    const bool compare =
        probe && (same_scene_as_last() || probe_carried_) && kept_.probe_ready && kept_.last.size() == n_;
    if (probe) {
        kept_.probe_ready = false;  // until this pass has written every entry
        kept_.last.resize(n_);
    }
    std::vector<unsigned char> inside_all(units, 1);
    run_units(units, parts, [&](std::size_t unit) {
        const auto [begin, end] = share_of(n_, unit, units);
        unsigned probe_inside = 1;
        float x_low = FLT_MAX, x_high = -FLT_MAX, y_low = FLT_MAX, y_high = -FLT_MAX;
        float height_sum = 0;
        std::uint32_t tallest_bits = 0;  // of the largest height: see below
        double total = 0;
        std::size_t first_bad = std::numeric_limits<std::size_t>::max();
        // Boxes of one scene mostly share their extent's exponent: counted
        // in one histogram, each count would wait for the one before it (a
        // store, then a load of the same place); in exponent_lanes of them,
        // box r counting in the (r % exponent_lanes)th, that many chains run
        // side by side. They are summed into the unit's partial at its end.
        constexpr std::size_t exponent_lanes = 4;
        std::array<std::array<std::uint32_t, 256>, exponent_lanes> exponents{};
        // A local copy: read through the lambda's capture, the stores below
        // (which might alias it, for all the compiler knows) made the loop
        // read it again for every box.
        const bool keys_on_grid = with_keys;
        // Heights are summed in float over runs and in double across them.
        bounds_run b;
        std::uint32_t extent_exponent[bounds_run::size];
        for (std::size_t run_begin = begin; run_begin < end; run_begin += bounds_run::size) {
            const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
            input_bounds(input, run_begin, run_end, b);
            for (std::size_t r = 0; r < run_end - run_begin; ++r) {
                const float height = b.hi_y[r] - b.lo_y[r];
                const float extent = std::max(b.hi_x[r] - b.lo_x[r], height);
                std::uint32_t bits;
                std::memcpy(&bits, &extent, sizeof bits);
                extent_exponent[r] = (bits >> 23) & 0xffu;
                // The bits of a height's magnitude order as its value does:
                // an integer maximum, which takes no branch on NaN (a row
                // that fails its check is refused below) and keeps -0 below
                // every height.
                std::uint32_t height_bits;
                std::memcpy(&height_bits, &height, sizeof height_bits);
                tallest_bits = std::max(tallest_bits, height_bits & 0x7fffffffu);
            }
            if (probe) {
                probe_motion(b, run_begin, run_end - run_begin, compare, probe_inside);
            }
            widen(b, run_end - run_begin);
            for (std::size_t i = run_begin; i < run_end; ++i) {
                // A row that fails its check has bounds of no meaning: it takes no part.
                if ((i < a_count_ ? check_a : check_b) && !valid_row(kind_, record_at(input, i))) {
                    first_bad = std::min(first_bad, i);
                    continue;
                }
                const std::size_t r = i - run_begin;
                ++exponents[r % exponent_lanes][extent_exponent[r]];
                if (keys_on_grid) {
                    key_by_id_[i] = grid_.key_of(b.lo_x[r], b.lo_y[r]);
                } else {
                    std::memcpy(&keys_[i], &b.lo_x[r], sizeof(float));
                    std::memcpy(&order_[i], &b.lo_y[r], sizeof(float));
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
        inside_all[unit] = static_cast<unsigned char>(probe_inside);
        partial& p = partials[unit];
        for (std::size_t e = 0; e < p.exponents.size(); ++e) {
            for (const std::array<std::uint32_t, 256>& lane : exponents) {
                p.exponents[e] += lane[e];
            }
        }
        p.x_low = clamp_finite(x_low);
        p.x_high = clamp_finite(x_high);
        p.y_low = clamp_finite(y_low);
        p.y_high = clamp_finite(y_high);
        p.height_sum = total + static_cast<double>(height_sum);
        std::memcpy(&p.tallest, &tallest_bits, sizeof p.tallest);
        p.first_bad = first_bad;
    });
    for (const partial& p : partials) {
        if (p.first_bad != std::numeric_limits<std::size_t>::max()) {
            refuse_row(input, p.first_bad);  // units are in order: the first bad row of all
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
    // How far the strip pass looks below a unit's first strip (strip_reach).
    tallest_ = 0;
    for (const partial& p : partials) {
        tallest_ = std::max(tallest_, p.tallest);
    }
    if (probe) {
        kept_.probe_ready = true;
        const bool calm = compare && std::find(inside_all.begin(), inside_all.end(), 0) == inside_all.end();
        kept_.calm_calls = calm ? kept_.calm_calls + 1 : 0;
        if (compare && !calm) {
            kept_.probe_skip = kept_.probe_wait;
            kept_.probe_wait = std::min(std::max<std::size_t>(1, 2 * kept_.probe_wait), max_probe_wait);
        } else if (calm) {
            kept_.probe_wait = 0;
        }
    }
    kept_.measured_typical_extent = median > 0 && median < 255 ? std::ldexp(1.0f, median - 127) : 0.0f;
}

}  // namespace obbsat::detail
