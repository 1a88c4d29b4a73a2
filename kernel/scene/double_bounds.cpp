// Before step 1 of a scene query over double rows (pair_search.hpp): the
// method's check, every row's check, and each row's float bounds rounded
// outward (obbsat/ref/bounds64.hpp) as the float rows the steps run on.
//
// Why the answer stays that of the double method over all pairs: each float
// row is the axis-aligned rectangle of its double rectangle's outward float
// bounds, whose corner bounds (obbsat/ref/bounds.hpp, least and greatest
// corner: exact) are those bounds again. Two double rectangles that share a
// point have exact bounds that overlap, so their outward float bounds do,
// and the sweep hands the pair to the double method (test_pairs).
#include "scene/pair_search.hpp"

#include "scene/outward_bounds.hpp"
#include "scene/search_common.hpp"
#include "support/work_shares.hpp"

#include <obbsat/collide64.hpp>
#include <obbsat/error.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect_records64.hpp>
#include <obbsat/ref/bounds64.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace obbsat::detail {

namespace {

/// Throws the double store's own message for row `id`, which valid_row
/// refused, with "a: " or "b: " in front in a query across two sets.
[[noreturn]] void refuse_double_row(const query_input& input, std::size_t id) {
    const bool second = id >= input.a_count;
    const std::size_t index = second ? id - input.a_count : id;
    const double* v = double_row_at(input, id);
    try {
        if (input.double_kind == store_kind::poses) {
            require_valid_pose(rect_pose64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}, index);
        } else {
            require_finite(rect64{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}}, index);
        }
    } catch (const invalid_input& e) {
        if (input.b64 == nullptr) {
            throw;
        }
        throw invalid_input(std::string(second ? "b: " : "a: ") + e.what());
    }
    throw std::logic_error("obbsat: a double row refused by the scene query passed its store's check");
}

/// The bits of a double, which the folds below test with integer
/// operations only: the compiler turns such loops into vector code, not
/// those of double compares, whose results are masks of another width.
inline std::uint64_t bits_of(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    return bits;
}

constexpr std::uint64_t magnitude_bits = 0x7fffffffffffffffu;
constexpr std::uint64_t exponent_bits = 0x7ff0000000000000u;

/// 1 when the double of `bits` is infinite or NaN (its exponent all ones), else 0.
inline std::uint64_t not_finite(std::uint64_t bits) {
    return ((bits & exponent_bits) + 0x0010000000000000u) >> 63;
}

/// 1 when the magnitude bits `magnitude` (sign cleared) are not those of a zero, else 0.
inline std::uint64_t not_zero(std::uint64_t magnitude) { return (magnitude + magnitude_bits) >> 63; }

/// 1 when the double of `bits` is below zero (negative, not -0), else 0.
inline std::uint64_t below_zero(std::uint64_t bits) { return (bits >> 63) & not_zero(bits & magnitude_bits); }

/// Whether each of `count` rows of `kind`, `stride` doubles apart, is a
/// valid row (valid_row), by folds with no branch a row: valid_row's test a
/// row, branch by branch, took about 2 % of find_pairs on a million
/// rect_pose64 rows. Rows whose stride is their field count (the unchecked
/// views: rect_pose64 and rect64 arrays) are one block of values, finite
/// or not, which the compiler turns into vector code. Only a run with a
/// refused row is read again, by valid_row, for its first one.
bool run_valid(store_kind kind, const double* rows, std::size_t stride, std::size_t count) {
    const std::size_t fields = kind == store_kind::poses ? 6 : 8;
    std::uint64_t refused = 0;
    if (stride == fields) {
        for (std::size_t k = 0; k < fields * count; ++k) {
            refused |= not_finite(bits_of(rows[k]));
        }
    } else {
        for (std::size_t r = 0; r < count; ++r) {
            for (std::size_t k = 0; k < fields; ++k) {
                refused |= not_finite(bits_of(rows[stride * r + k]));
            }
        }
    }
    if (kind == store_kind::poses) {
        for (std::size_t r = 0; r < count; ++r) {
            const double* v = rows + stride * r;
            refused |= below_zero(bits_of(v[2])) | below_zero(bits_of(v[3]));
            refused |= not_zero((bits_of(v[4]) | bits_of(v[5])) & magnitude_bits) ^ 1u;
        }
    }
    return refused == 0;
}

}  // namespace

void require_method_on_double_rows(const collide_options& options, store_kind kind) {
    if (!is_method(options.test)) {
        throw invalid_input("collide_options::test holds " + std::to_string(static_cast<unsigned>(options.test)) +
                            ", which names no method");
    }
    if (!runs_on_doubles(options.test, kind)) {
        std::string offered;
        for (const method m : methods_on_doubles(kind)) {
            offered += std::string(offered.empty() ? "" : ", ") + method_name(m);
        }
        throw invalid_input(std::string("method ") + method_name(options.test) + " does not run on double " +
                            (kind == store_kind::poses ? "poses" : "corners") + " (they take " + offered + ")");
    }
}

query_input pair_search::bound_doubles(const query_input& input) {
    double_bounds_seconds_ = 0;
    if (!input.doubles) {
        return input;
    }
    require_method_on_double_rows(options_, input.double_kind);
    const auto start = clock_type::now();
    const bool self = input.b64 == nullptr;
    const std::size_t n = input.a_count + (self ? 0 : input.b_count);
    double_bounds_.resize(n);
    const std::size_t parts = parts_for(n, options_.threads, min_boxes_per_part);
    const std::size_t units = units_for(n, parts, min_boxes_per_unit);
    std::vector<std::size_t> first_bad(units, std::numeric_limits<std::size_t>::max());
    const bool poses = input.double_kind == store_kind::poses;
    run_units(units, parts, [&](std::size_t unit) {
        const auto [begin, end] = share_of(n, unit, units);
        static_assert(double_bounds_run::size <= bounds_run::size, "a run of bounds holds a run of rows");
        double_bounds_run staged;
        bounds_run rounded;
        for (std::size_t run_begin = begin, run_end = begin; run_begin < end; run_begin = run_end) {
            // A run stays within one set, whose rows are evenly spaced.
            const std::size_t set_end = run_begin < input.a_count ? std::min(end, input.a_count) : end;
            run_end = std::min(set_end, run_begin + double_bounds_run::size);
            const std::size_t count = run_end - run_begin;
            const bool checked = run_begin < input.a_count ? input.a64_checked : input.b64_checked;
            const double* rows = double_row_at(input, run_begin);
            const std::size_t stride = run_begin < input.a_count ? input.a64_stride : input.b64_stride;
            if (!checked && !run_valid(input.double_kind, rows, stride, count)) {
                for (std::size_t id = run_begin; id < run_end; ++id) {
                    if (!valid_row(input.double_kind, double_row_at(input, id))) {
                        first_bad[unit] = std::min(first_bad[unit], id);
                        break;
                    }
                }
            }
            // A row refused above gets bounds too (NaN in, NaN out): the query throws before reading them.
            if (poses) {
                stage_pose_bounds(rows, stride, count, staged);
            } else {
                stage_corner_bounds(rows, stride, count, staged);
            }
            round_bounds_outward(staged, count, rounded.lo_x, rounded.lo_y, rounded.hi_x, rounded.hi_y);
            for (std::size_t r = 0; r < count; ++r) {
                // UL, UR, LR, LL of the bounds: a corner row whose bounds are these exactly.
                float* row = double_bounds_[run_begin + r].v;
                row[0] = rounded.lo_x[r], row[1] = rounded.hi_y[r], row[2] = rounded.hi_x[r], row[3] = rounded.hi_y[r];
                row[4] = rounded.hi_x[r], row[5] = rounded.lo_y[r], row[6] = rounded.lo_x[r], row[7] = rounded.lo_y[r];
            }
        }
    });
    for (const std::size_t bad : first_bad) {
        if (bad != std::numeric_limits<std::size_t>::max()) {
            refuse_double_row(input, bad);  // units are in order: the first bad row of all
        }
    }
    double_bounds_seconds_ = seconds_since(start);
    static const float none[8] = {};
    query_input out = input;
    out.kind = store_kind::corners;
    out.a = n == 0 ? none : double_bounds_.data()->v;
    out.a_stride = 8;
    out.a_checked = true;
    if (!self) {
        out.b = input.b_count == 0 ? none : double_bounds_[input.a_count].v;
        out.b_stride = 8;
        out.b_checked = true;
    }
    return out;
}

}  // namespace obbsat::detail
