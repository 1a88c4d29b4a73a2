// Step 2 of the scene query (pair_search.hpp), second half: the records copied into the query's order.
#include "scene/pair_search.hpp"

#include "dispatch/backend_registry.hpp"
#include "scene/outward_bounds.hpp"
#include "scene/search_common.hpp"
#include "support/fetch_ahead.hpp"
#include "support/work_shares.hpp"

#include <algorithm>
#include <new>

namespace obbsat::detail {

void pair_search::store_sweep_bounds(const bounds_run& b, std::size_t run_begin, std::size_t run_end) {
    // The grid's maps (strip_grid::q_of, strip_of) written out on locals and
    // pointers that alias nothing, so that the loop runs with no branch and
    // reads nothing again after each store.
    const double x_low = grid_.x_low, x_scale = grid_.x_scale, y_low = grid_.y_low, y_scale = grid_.y_scale;
    const std::uint32_t q_top = grid_.q_max, strip_top = grid_.strips - 1;
    const std::size_t count = run_end - run_begin;
    float* __restrict const lo_x = in_lo_x_.data() + run_begin;
    float* __restrict const lo_y = in_lo_y_.data() + run_begin;
    float* __restrict const hi_x = in_hi_x_.data() + run_begin;
    float* __restrict const hi_y = in_hi_y_.data() + run_begin;
    std::uint32_t* __restrict const q_lo = q_lo_.data() + run_begin;
    std::uint32_t* __restrict const q_hi = q_hi_.data() + run_begin;
    std::uint32_t* __restrict const strip_hi = strip_hi_.data() + run_begin;
    for (std::size_t r = 0; r < count; ++r) {
        lo_x[r] = b.lo_x[r];
        lo_y[r] = b.lo_y[r];
        hi_x[r] = b.hi_x[r];
        hi_y[r] = b.hi_y[r];
        q_lo[r] = strip_grid::clamped_floor((static_cast<double>(b.lo_x[r]) - x_low) * x_scale, q_top);
        q_hi[r] = strip_grid::clamped_floor((static_cast<double>(b.hi_x[r]) - x_low) * x_scale, q_top);
        strip_hi[r] = strip_grid::clamped_floor((static_cast<double>(b.hi_y[r]) - y_low) * y_scale, strip_top);
    }
}

void pair_search::copy_records(const query_input& input, std::size_t parts) {
    // A double query that keeps nothing and computes no contacts reads no
    // float row in its order: the sweep takes the bounds bound_doubles made
    // and the double method the double records.
    const bool bounds_only = double_records_only();
    if (!bounds_only) {
        records_.resize(n_);
    }
    if (doubles_) {
        records64_.resize(n_);
    }
    in_lo_x_.resize(n_);
    in_lo_y_.resize(n_);
    in_hi_x_.resize(n_);
    in_hi_y_.resize(n_);
    q_lo_.resize(n_);
    q_hi_.resize(n_);
    strip_hi_.resize(n_);
    side_.resize(n_);
    if (filtered_) {
        filters_.resize(n_);
    }
    if (kept_.keep) {
        kept_.now.resize(n_);
    }
    const bounds_fn bounds = kernels_for(ran_).bounds;
    const std::size_t units = units_for(n_, parts, min_boxes_per_unit);  // taken as they come
    const auto copy_unit = [&](std::size_t unit) {
        const auto [begin, end] = share_of(n_, unit, units);
        constexpr std::size_t ahead = random_rows_ahead;
        bounds_run b;
        if (bounds_only) {
            copy_double_records(input, begin, end);
            return;
        }
        for (std::size_t run_begin = begin; run_begin < end; run_begin += bounds_run::size) {
            const std::size_t run_end = std::min(end, run_begin + bounds_run::size);
            for (std::size_t k = run_begin; k < run_end; ++k) {
                if (k + ahead < end) {
                    fetch_into_l2(record_at(input, order_[k + ahead]));
                    if (doubles_) {
                        fetch_into_l2(double_row_at(input, order_[k + ahead]));
                    }
                }
                const std::uint32_t id = order_[k];
                ::new (static_cast<void*>(&records_[k])) record;  // its memory may have held the sort's words
                copy_row(input, id, records_[k].v);
                if (doubles_) {
                    // The double method reads these (test_pairs), in the query's order as the floats.
                    copy_double_row(input, id, records64_[k].v);
                }
                side_[k] = id >= a_count_ && !self_ ? 1 : 0;
            }
            if (filtered_) {
                // Beside the records, in the same order: the sweep reads a
                // candidate's two entries where it reads their bounds.
                for (std::size_t k = run_begin; k < run_end; ++k) {
                    filters_[k] = filter_of(input, order_[k]);
                }
            }
            // The same function on the same floats as the extent pass: the bounds of step 1.
            bounds(kind_, records_[run_begin].v, run_end - run_begin, b.lo_x, b.lo_y, b.hi_x, b.hi_y);
            if (kept_.keep) {
                // The bounds themselves for the kept candidates' test, the widened ones for the sweep.
                for (std::size_t k = run_begin; k < run_end; ++k) {
                    kept_.now[k] = signed_bounds_of(b, k - run_begin);
                }
                widen(b, run_end - run_begin);
            }
            store_sweep_bounds(b, run_begin, run_end);
        }
    };
    start_visit_counts(units);
    run_units(units, parts, [&](std::size_t unit) {
        copy_unit(unit);
        // The visits' first pass, over the strips the unit has just written (visits.cpp).
        const auto [begin, end] = share_of(n_, unit, units);
        count_visits(unit, begin, end);
    });
}

void pair_search::copy_double_records(const query_input& input, std::size_t begin, std::size_t end) {
    // The bounds in the query's order are those bound_doubles made, computed
    // again (outward_bounds.hpp, the same floats) from the double records
    // just copied, which are in the cache: cheaper than reading each row's
    // float bounds from wherever the caller's order put it.
    constexpr std::size_t ahead = random_rows_ahead;
    const std::uint32_t* const order = order_.data();
    static_assert(double_bounds_run::size <= bounds_run::size, "a run of bounds holds a run of rows");
    double_bounds_run staged;
    bounds_run rounded;
    for (std::size_t run_begin = begin; run_begin < end; run_begin += double_bounds_run::size) {
        const std::size_t run_end = std::min(end, run_begin + double_bounds_run::size);
        const std::size_t count = run_end - run_begin;
        for (std::size_t k = run_begin; k < run_end; ++k) {
            if (k + ahead < end) {
                // A 48-byte row may span two cache lines: both are fetched.
                const double* next = double_row_at(input, order[k + ahead]);
                fetch_into_l2(next);
                fetch_into_l2(next + 5);
            }
            const std::uint32_t id = order[k];
            ::new (static_cast<void*>(&records64_[k])) record64;  // its memory may have held the sort's words
            copy_double_row(input, id, records64_[k].v);
            side_[k] = id >= a_count_ && !self_ ? 1 : 0;
        }
        const double* rows = records64_[run_begin].v;
        if (double_kind_ == store_kind::poses) {
            stage_pose_bounds(rows, 8, count, staged);
        } else {
            stage_corner_bounds(rows, 8, count, staged);
        }
        round_bounds_outward(staged, count, rounded.lo_x, rounded.lo_y, rounded.hi_x, rounded.hi_y);
        store_sweep_bounds(rounded, run_begin, run_end);
        if (filtered_) {
            for (std::size_t k = run_begin; k < run_end; ++k) {
                filters_[k] = filter_of(input, order[k]);
            }
        }
    }
}

}  // namespace obbsat::detail
