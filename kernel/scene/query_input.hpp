// The rows of a scene query (pair_search.hpp) where the caller keeps them:
// which row an index names, copying one, checking one, its bounds. Used by
// every step that reads the input. Internal to the library, baseline ISA.
#pragma once

#include "scene/filter_values.hpp"
#include "store/finite_check.hpp"
#include "store/pose_record.hpp"

#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pair_filters.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/ref/bounds.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace obbsat {
class box_view;
}

namespace obbsat::detail {

/// The rectangles of one query: one or two sets of one kind, each rows of
/// `stride` floats (a pose's first six floats are cx, cy, hx, hy, c, s; a
/// corner row's eight are UL, UR, LR, LL). A set not `checked` is checked by
/// the pass that computes the bounds.
struct query_input {
    store_kind kind = store_kind::poses;
    const float* a = nullptr;  ///< the first set
    std::size_t a_count = 0;
    std::size_t a_stride = 8;
    bool a_checked = true;
    const float* b = nullptr;  ///< the second set; nullptr for a query within a
    std::size_t b_count = 0;
    std::size_t b_stride = 8;
    bool b_checked = true;
    pair_filters a_filters;  ///< the first set's pair filters (obbsat/pair_filters.hpp)
    pair_filters b_filters;  ///< the second set's; unused within one set

    /// Double rows (box_view::precision() double): the float rows above are
    /// then their float bounds rounded outward (obbsat/ref/bounds64.hpp) as
    /// corner rows, checked, made by pair_search::bound_doubles; the sweep
    /// runs on them and the double method decides the candidates on these.
    bool doubles = false;
    store_kind double_kind = store_kind::poses;  ///< of the double rows
    const double* a64 = nullptr;  ///< the first set's double rows
    std::size_t a64_stride = 8;   ///< doubles from one row to the next: 6 for rect_pose64 rows, else 8
    bool a64_checked = true;
    const double* b64 = nullptr;  ///< the second set's; nullptr within one set
    std::size_t b64_stride = 8;
    bool b64_checked = true;

    /// True iff some set of the query carries pair filters: the query then
    /// takes the filtered path, chosen once (pair_search::filtered_).
    bool filtered() const { return a_filters.any() || (b != nullptr && b_filters.any()); }

    /// The caller's ids of the rows (box_view::with_ids), one per row of a
    /// and of b; with_ids false when the rows carry none.
    bool with_ids = false;
    const std::uint64_t* a_ids = nullptr;
    const std::uint64_t* b_ids = nullptr;
};

/// Row `id` of the query: of the first set below a_count, else of the second.
inline const float* record_at(const query_input& input, std::size_t id) {
    return id < input.a_count ? input.a + input.a_stride * id : input.b + input.b_stride * (id - input.a_count);
}

/// The filters of row `id` of the query, defaults where its set gives none.
inline filter_values filter_of(const query_input& input, std::size_t id) {
    return id < input.a_count ? filter_values_of(input.a_filters, id)
                              : filter_values_of(input.b_filters, id - input.a_count);
}

inline std::size_t stride_of(const query_input& input, std::size_t id) {
    return id < input.a_count ? input.a_stride : input.b_stride;
}

/// True iff the values of one row are a valid rectangle of its kind (finite_check.hpp).
inline bool valid_row(store_kind kind, const float* v) {
    return kind == store_kind::poses ? valid_pose_row(v) : all_finite(v, 8);
}

/// True iff the doubles of one row are a valid rectangle of `kind`: finite,
/// and for a pose no negative half extent and a rotation vector not zero.
inline bool valid_row(store_kind kind, const double* v) {
    const int values = kind == store_kind::poses ? 6 : 8;
    bool finite = true;
    for (int k = 0; k < values; ++k) {
        finite &= std::isfinite(v[k]);
    }
    return kind == store_kind::poses ? finite && !(v[2] < 0.0) && !(v[3] < 0.0) && !(v[4] == 0.0 && v[5] == 0.0)
                                     : finite;
}

/// Throws invalid_input unless options.test names a method that runs on
/// double rows of `kind` (obbsat/collide64.hpp); the message names those
/// methods. [double_bounds.cpp]
void require_method_on_double_rows(const collide_options& options, store_kind kind);

/// Double row `id` of the query: of the first set below a_count, else of the second.
inline const double* double_row_at(const query_input& input, std::size_t id) {
    return id < input.a_count ? input.a64 + input.a64_stride * id
                              : input.b64 + input.b64_stride * (id - input.a_count);
}

/// Copies double row `id` into a 64-byte record (a pose's two last doubles zero).
inline void copy_double_row(const query_input& input, std::size_t id, double* out) {
    const double* row = double_row_at(input, id);
    const std::size_t stride = id < input.a_count ? input.a64_stride : input.b64_stride;
    std::memcpy(out, row, (stride == 6 ? 6 : 8) * sizeof(double));
    if (stride == 6) {
        out[6] = 0.0;
        out[7] = 0.0;
    }
}

/// Throws the store's own message for row `id` of the query, which valid_row
/// refused: "pose 7: ..." or "rectangle 7: ...", with "a: " or "b: " in front
/// in a query across two sets.
[[noreturn]] void refuse_row(const query_input& input, std::size_t id);

/// Checks every row of the sets not `checked` and refuses the first invalid
/// one (refuse_row): for a query with nothing to compare, which reads no
/// bounds, so that it refuses what a larger one would.
void require_valid_rows(const query_input& input);

inline ref::box_bounds bounds_of_record(store_kind kind, const float* v) {
    if (kind == store_kind::poses) {
        return ref::bounds_of(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}});
    }
    return ref::bounds_of(rect{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}});
}

/// Copies row `id` of the query into `out` (a pose row's two last floats zero).
inline void copy_row(const query_input& input, std::size_t id, float* out) {
    const float* row = record_at(input, id);
    if (stride_of(input, id) == 8) {
        std::memcpy(out, row, 8 * sizeof(float));
    } else {
        widen_pose_row(out, row);
    }
}

/// The query over `a`, and `b` when it is not nullptr (a query across two
/// sets); the rows' ids only `with_ids` (pair_finder). Throws invalid_input
/// when the sets differ in kind or precision, or only one carries ids. [find_pairs.cpp]
query_input input_of(const box_view& a, const box_view* b, bool with_ids = false);

}  // namespace obbsat::detail
