// The scalar backend: the reference of each method of method_catalogue.hpp
// applied one pair at a time.
#include "dispatch/backend_catalogue.hpp"
#include "dispatch/kernel_table.hpp"
#include "methods/method_catalogue.hpp"
#include "store/pose_record.hpp"

#include <obbsat/ref/bounds.hpp>
#include <obbsat/ref/pose_corners.hpp>

#include <algorithm>
#include <cmath>

namespace obbsat::detail {

namespace {

// A method with a slow path has the exact oracle as its reference: on the
// scalar path every pair counts as decided on the exact path.
template <bool SlowPath>
std::size_t exact_count(std::size_t count) {
    return SlowPath ? count : 0;
}

template <reference_fn Reference, bool SlowPath>
std::size_t stream_pairs(const soa_view& a, const soa_view& b, std::size_t count, std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(rect_at(a, i), rect_at(b, i)) ? 1 : 0;
    }
    return exact_count<SlowPath>(count);
}

template <reference_fn Reference, bool SlowPath>
std::size_t indexed_pairs(const soa_view& rects, const pair_index* pairs, std::size_t count,
                          std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(rect_at(rects, pairs[i].a), rect_at(rects, pairs[i].b)) ? 1 : 0;
    }
    return exact_count<SlowPath>(count);
}

template <reference_fn Reference, bool SlowPath>
std::size_t indexed_records(const rect* records, const pair_index* pairs, std::size_t count,
                            std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(records[pairs[i].a], records[pairs[i].b]) ? 1 : 0;
    }
    return exact_count<SlowPath>(count);
}

template <pose_reference_fn Reference, bool SlowPath>
std::size_t pose_stream_pairs(const float* a, const float* b, std::size_t count, std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(pose_record_at(a, i), pose_record_at(b, i)) ? 1 : 0;
    }
    return exact_count<SlowPath>(count);
}

template <pose_reference_fn Reference, bool SlowPath>
std::size_t pose_indexed_pairs(const float* records, const pair_index* pairs, std::size_t count,
                               std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(pose_record_at(records, pairs[i].a), pose_record_at(records, pairs[i].b)) ? 1 : 0;
    }
    return exact_count<SlowPath>(count);
}

template <pose_reference_fn Reference, bool SlowPath>
std::size_t pose_stream_soa_pairs(const pose_soa_view& a, const pose_soa_view& b, std::size_t count,
                                  std::uint8_t* verdicts) {
    for (std::size_t i = 0; i < count; ++i) {
        verdicts[i] = Reference(pose_at(a, i), pose_at(b, i)) ? 1 : 0;
    }
    return exact_count<SlowPath>(count);
}

/// The sweep of one strip (strip_view.hpp), one entry pair at a time.
std::size_t strip_sweep(const strip_view& strip, sweep_cursor& cursor, pair_index* out, std::size_t capacity) {
    const std::size_t m = strip.size;
    std::size_t count = 0;
    std::size_t e = cursor.e;
    std::size_t f = cursor.f;
    for (; e + 1 < m; ++e, f = e + 1) {
        for (; f < m && strip.q_lo[f] <= strip.q_hi[e]; ++f) {
            if (capacity - count < strip_padding) {
                cursor = sweep_cursor{e, f};
                return count;
            }
            const bool one_starts = strip.starts[e] > 0.0f || strip.starts[f] > 0.0f;
            const bool mixes = !strip.cross || strip.store[e] != strip.store[f];
            if (one_starts && mixes && strip.lo_x[f] <= strip.hi_x[e] && strip.hi_x[f] >= strip.lo_x[e] &&
                strip.lo_y[f] <= strip.hi_y[e] && strip.hi_y[f] >= strip.lo_y[e]) {
                out[count++] = pair_index{static_cast<std::uint32_t>(strip.id[e]), static_cast<std::uint32_t>(strip.id[f])};
            }
        }
    }
    cursor = sweep_cursor{m, m + 1};
    return count;
}

void pose_corners(const float* records, std::size_t count, rect* out) {
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = ref::corners_of(pose_record_at(records, i));
    }
}

void bounds(store_kind kind, const float* records, std::size_t count, float* lo_x, float* lo_y, float* hi_x,
            float* hi_y) {
    for (std::size_t i = 0; i < count; ++i) {
        const float* v = records + 8 * i;
        const ref::box_bounds b = kind == store_kind::poses
                                      ? ref::bounds_of(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}})
                                      : ref::bounds_of(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
        lo_x[i] = b.lo_x;
        lo_y[i] = b.lo_y;
        hi_x[i] = b.hi_x;
        hi_y[i] = b.hi_y;
    }
}

std::uint32_t largest_index(const pair_index* pairs, std::size_t count) {
    std::uint32_t largest = 0;
    for (std::size_t i = 0; i < count; ++i) {
        largest = std::max(largest, std::max(pairs[i].a, pairs[i].b));
    }
    return largest;
}

void fused_multiply_add(const float* x, const float* y, const float* z, std::size_t count, float* out) {
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = std::fma(x[i], y[i], z[i]);
    }
}

/// The entry points of one catalogue row on corners; all null when the row
/// does not run on corners. The scalar path fetches nothing ahead, so its
/// near and far variants are indexed_records itself.
template <class Row>
constexpr method_kernels kernels_of_row() {
    method_kernels k{};
    if constexpr (offered<typename Row::corners>) {
        constexpr reference_fn reference = Row::corners::reference;
        k.stream = stream_pairs<reference, Row::has_slow_path>;
        k.indexed = indexed_pairs<reference, Row::has_slow_path>;
        k.indexed_records = indexed_records<reference, Row::has_slow_path>;
        k.indexed_records_near = indexed_records<reference, Row::has_slow_path>;
        k.indexed_records_far = indexed_records<reference, Row::has_slow_path>;
    }
    return k;
}

/// The entry points of one catalogue row on poses; all null when the row
/// does not run on poses.
template <class Row>
constexpr pose_method_kernels pose_kernels_of_row() {
    pose_method_kernels k{};
    if constexpr (offered<typename Row::poses>) {
        constexpr pose_reference_fn reference = Row::poses::reference;
        k.stream = pose_stream_pairs<reference, Row::has_slow_path>;
        k.indexed = pose_indexed_pairs<reference, Row::has_slow_path>;
        k.stream_soa = pose_stream_soa_pairs<reference, Row::has_slow_path>;
        k.indexed_near = pose_indexed_pairs<reference, Row::has_slow_path>;
        k.indexed_far = pose_indexed_pairs<reference, Row::has_slow_path>;
    }
    return k;
}

template <class... Rows>
constexpr kernel_table table_of(type_list<Rows...>) {
    kernel_table t{};
    ((t.methods[row_of(Rows::id)] = kernels_of_row<Rows>()), ...);
    ((t.pose_methods[row_of(Rows::id)] = pose_kernels_of_row<Rows>()), ...);
    t.fused_multiply_add = fused_multiply_add;
    t.pose_corners = pose_corners;
    t.strip_sweep = strip_sweep;
    t.bounds = bounds;
    t.largest_index = largest_index;
    return t;
}

}  // namespace

template <>
const kernel_table& kernels_of<scalar_backend>() {
    static constexpr kernel_table table = table_of(method_catalogue{});
    static_assert(!__builtin_constant_p(follows_catalogue(table, method_catalogue{})) ||
                      follows_catalogue(table, method_catalogue{}),
                  "the table holds the catalogue's rows");
    return table;
}

}  // namespace obbsat::detail
