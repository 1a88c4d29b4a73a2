// The entry points one backend provides, per method. The dispatcher holds one
// table per backend; nothing in a table may be called before the dispatcher
// has checked that the CPU runs that backend.
//
// The per-ISA kernels include this header: it may hold only types, constants,
// declarations and functions of internal linkage that they call
// (kernel/lanes/README.md, checked by `ctest -R isa_boundary`).
#pragma once

#include "dispatch/pose_soa_view.hpp"
#include "dispatch/soa_view.hpp"
#include "dispatch/strip_view.hpp"
#include "methods/method_catalogue.hpp"

#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

// Every entry returns how many pairs it decided on the method's exact slow
// path (always 0 for methods without one).

/// verdicts[i] = method(a[i], b[i]) for i < count; reads only a[0..count), b[0..count).
using stream_fn = std::size_t (*)(const soa_view& a, const soa_view& b, std::size_t count,
                           std::uint8_t* verdicts);

/// verdicts[i] = method(rects[pairs[i].a], rects[pairs[i].b]) for i < count;
/// every index must be < rects.size (the caller checks).
using indexed_fn = std::size_t (*)(const soa_view& rects, const pair_index* pairs, std::size_t count,
                            std::uint8_t* verdicts);

/// verdicts[i] = method(records[pairs[i].a], records[pairs[i].b]) for i < count,
/// over packed 32-byte records; every index must be in range (the caller checks).
using indexed_records_fn = std::size_t (*)(const rect* records, const pair_index* pairs, std::size_t count,
                                    std::uint8_t* verdicts);

/// out[i] = x[i] * y[i] + z[i] rounded once, as the backend's lanes compute
/// it inside the methods that fuse (conservative). Exposed so that the SSE2
/// emulation can be checked against std::fma directly.
using fused_multiply_add_fn = void (*)(const float* x, const float* y, const float* z, std::size_t count,
                                       float* out);

/// verdicts[i] = method(a[i], b[i]) for i < count over 32-byte pose records
/// (pose_records' layout).
using pose_stream_fn = std::size_t (*)(const float* a, const float* b, std::size_t count,
                                       std::uint8_t* verdicts);

/// verdicts[i] = method(records[pairs[i].a], records[pairs[i].b]) for i < count
/// over 32-byte pose records; every index must be in range (the caller checks).
using pose_indexed_fn = std::size_t (*)(const float* records, const pair_index* pairs, std::size_t count,
                                        std::uint8_t* verdicts);

/// verdicts[i] = method(a[i], b[i]) for i < count over two pose_soa stores.
using pose_stream_soa_fn = std::size_t (*)(const pose_soa_view& a, const pose_soa_view& b, std::size_t count,
                                           std::uint8_t* verdicts);

/// out[i] = ref::corners_of(pose i) for i < count over 32-byte pose records.
using pose_corners_fn = void (*)(const float* records, std::size_t count, rect* out);

/// lo_x[i], lo_y[i], hi_x[i], hi_y[i] = ref::bounds_of(record i) for i < count,
/// over 32-byte records of `kind` (pose records or corner records).
using bounds_fn = void (*)(store_kind kind, const float* records, std::size_t count, float* lo_x, float* lo_y,
                           float* hi_x, float* hi_y);

/// The largest of pairs[i].a and pairs[i].b over i < count, 0 when count is 0:
/// the pass that checks a pair list against its store.
using largest_index_fn = std::uint32_t (*)(const pair_index* pairs, std::size_t count);

/// One method's entry points on the corner stores of one backend; all null
/// when the method does not run on corners.
struct method_kernels {
    stream_fn stream;
    indexed_fn indexed;
    indexed_records_fn indexed_records;
    /// indexed_records for a list whose pairs' records lie near the records of
    /// the pairs before them (the scene queries'), or over a store that fits
    /// in L2 (store_bytes_in_l2): the same verdicts, without fetching records
    /// ahead, which there only costs instructions.
    indexed_records_fn indexed_records_near;
    /// indexed_records for a store read from DRAM (more than
    /// store_bytes_from_dram): the same verdicts, the records of pairs further
    /// ahead fetched into L2.
    indexed_records_fn indexed_records_far;
};

/// One method's entry points on the pose store of one backend; all null when
/// the method does not run on poses.
struct pose_method_kernels {
    pose_stream_fn stream;
    pose_indexed_fn indexed;
    pose_stream_soa_fn stream_soa;
    /// indexed for a list whose pairs' records lie near each other (see
    /// method_kernels::indexed_records_near).
    pose_indexed_fn indexed_near;
    /// indexed for a store read from DRAM (see method_kernels::indexed_records_far).
    pose_indexed_fn indexed_far;
};

struct kernel_table {
    method_kernels methods[method_count];            ///< row k is obbsat::method k (method_catalogue.hpp)
    pose_method_kernels pose_methods[method_count];  ///< the same rows, on poses
    fused_multiply_add_fn fused_multiply_add;
    pose_corners_fn pose_corners;
    strip_sweep_fn strip_sweep;  ///< the scene queries' broadphase, one strip
    bounds_fn bounds;            ///< the scene queries' bounds (obbsat/ref/bounds.hpp)
    largest_index_fn largest_index;

    /// The entry points of `m` on corners; the caller has checked is_method.
    const method_kernels& of(method m) const { return methods[static_cast<std::size_t>(m)]; }
    /// The entry points of `m` on poses; the caller has checked is_method.
    const pose_method_kernels& on_poses(method m) const { return pose_methods[static_cast<std::size_t>(m)]; }
};

/// The table of one backend of backend_catalogue.hpp: defined by
/// scalar_kernels.cpp for the scalar path and by lanes/backend_isa/verdict_kernels.cpp, once per
/// SIMD instruction set, for the others. Both fill every entry by its name,
/// each method's row at row_of(its id), and check the result with
/// follows_catalogue.
template <class Backend>
const kernel_table& kernels_of();

namespace {

/// The row of `m` in kernel_table::methods and kernel_table::pose_methods.
constexpr std::size_t row_of(method m) { return static_cast<std::size_t>(m); }

constexpr bool all_set(const method_kernels& k) {
    return k.stream && k.indexed && k.indexed_records && k.indexed_records_near && k.indexed_records_far;
}

constexpr bool all_null(const method_kernels& k) {
    return !k.stream && !k.indexed && !k.indexed_records && !k.indexed_records_near && !k.indexed_records_far;
}

constexpr bool all_set(const pose_method_kernels& k) {
    return k.stream && k.indexed && k.stream_soa && k.indexed_near && k.indexed_far;
}

constexpr bool all_null(const pose_method_kernels& k) {
    return !k.stream && !k.indexed && !k.stream_soa && !k.indexed_near && !k.indexed_far;
}

/// Whether `table` holds what the catalogue (method_catalogue.hpp) says: the
/// row of each method on each store has every entry point where the catalogue
/// offers the method on that store and none where it does not, and every
/// entry outside the rows is set. Checked as
///   static_assert(!__builtin_constant_p(follows_catalogue(...)) || follows_catalogue(...))
/// because under -fsanitize=undefined (which implies -fno-delete-null-pointer-checks)
/// GCC does not fold a function's address compared with null: there the check
/// holds vacuously, and every other build, the release suite's among them,
/// enforces it. A null entry is still caught under the sanitizer.
template <class... Rows>
constexpr bool follows_catalogue(const kernel_table& table, type_list<Rows...>) {
    const bool corner_rows = ((offered<typename Rows::corners> ? all_set(table.methods[row_of(Rows::id)])
                                                               : all_null(table.methods[row_of(Rows::id)])) &&
                              ...);
    const bool pose_rows = ((offered<typename Rows::poses> ? all_set(table.pose_methods[row_of(Rows::id)])
                                                           : all_null(table.pose_methods[row_of(Rows::id)])) &&
                            ...);
    return corner_rows && pose_rows && table.fused_multiply_add && table.pose_corners && table.strip_sweep &&
           table.bounds && table.largest_index;
}

}  // namespace

}  // namespace obbsat::detail
