// The kernel tables of the double stores: the entry points one SIMD backend
// offers for pair lists over pose_records64 (one double pose per lane) and
// over rect_records64 (one double-corner rectangle per lane), defined by
// kernel/lanes/backend_isa/double_kernels.cpp compiled once per SIMD backend, and found at
// the baseline by double_kernels_for and corner64_kernels_for. Internal to
// the library.
#pragma once

#include "dispatch/pose_soa64_view.hpp"

#include <obbsat/backend.hpp>
#include <obbsat/method.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {

/// verdicts[i] = the method's verdict on records[pairs[i].a] and records[pairs[i].b]
/// (pose_records64 records, 8 doubles each) for i < count; returns how many pairs
/// the exact slow path settled (0 but for exact).
using pose64_indexed_fn = std::size_t (*)(const double* records, const pair_index* pairs, std::size_t count,
                                          std::uint8_t* verdicts);

/// verdicts[i] = the method's verdict on a[i] and b[i] (pose_records64 records) for
/// i < count; returns how many pairs the exact slow path settled (0 but for exact).
using pose64_stream_fn = std::size_t (*)(const double* a, const double* b, std::size_t count,
                                         std::uint8_t* verdicts);

/// verdicts[i] = the method's verdict on a[i] and b[i] (two pose_soa64 views) for
/// i < count; returns how many pairs the exact slow path settled.
using pose64_stream_soa_fn = std::size_t (*)(const pose_soa64_view& a, const pose_soa64_view& b, std::size_t count,
                                             std::uint8_t* verdicts);

/// The entry points of one method on double poses besides the pair list that
/// fetches nothing ahead: pair lists fetching the records of pairs ahead
/// (support/fetch_ahead.hpp), and streams over records and over arrays.
struct pose64_method_kernels {
    pose64_indexed_fn indexed_fetching;  ///< 16 pairs ahead into L1: a store beyond L2, within L3
    pose64_indexed_fn indexed_far;       ///< 128 pairs ahead into L2: a store read from DRAM
    pose64_stream_fn stream;
    pose64_stream_soa_fn stream_soa;
};

/// The entry points of one backend on double poses, per method that runs there:
/// `exact`, `conservative` and `local` decide pair lists fetching nothing ahead
/// (records the caches hold: the scene query's rows, a store within L2); the
/// *_kernels rows the rest.
struct double_kernel_table {
    pose64_indexed_fn exact;
    pose64_indexed_fn conservative;
    pose64_indexed_fn local;
    pose64_method_kernels exact_kernels;
    pose64_method_kernels conservative_kernels;
    pose64_method_kernels local_kernels;
};

/// The table of Backend (a SIMD row of dispatch/backend_catalogue.hpp), defined in
/// its per-ISA object (lanes/backend_isa/double_kernels.cpp).
template <class Backend>
const double_kernel_table& double_kernels_of();

/// The scalar references of `m` (exact, conservative or local) over pose_records64
/// records, as a pose64_indexed_fn: exact through the certified path, else the oracle.
std::size_t scalar_pose64_indexed(method m, const double* records, const pair_index* pairs, std::size_t count,
                                  std::uint8_t* verdicts);

/// The scalar references of `m` over two pose_records64 record arrays, a[i]
/// against b[i], as a pose64_stream_fn.
std::size_t scalar_pose64_stream(method m, const double* a, const double* b, std::size_t count,
                                 std::uint8_t* verdicts);

/// The same over two pose_soa64 views, as a pose64_stream_soa_fn.
std::size_t scalar_pose64_stream_soa(method m, const pose_soa64_view& a, const pose_soa64_view& b, std::size_t count,
                                     std::uint8_t* verdicts);

/// The scalar references of `m` (exact or conservative) over rect64 rows (8 doubles each).
std::size_t scalar_rect64_indexed(method m, const double* records, const pair_index* pairs, std::size_t count,
                                  std::uint8_t* verdicts);

/// The table of `resolved` (a backend this CPU runs), or nullptr for the scalar
/// backend and for a backend not compiled into this build.
const double_kernel_table* double_kernels_for(backend resolved);

/// verdicts[i] = the method's verdict on records[pairs[i].a] and records[pairs[i].b]
/// (rect_records64 records) for i < count; returns how many pairs the exact slow
/// path settled (0 but for exact).
using rect64_indexed_fn = std::size_t (*)(const rect64* records, const pair_index* pairs, std::size_t count,
                                          std::uint8_t* verdicts);

/// The pair lists of one method on double corners that fetch the records of
/// pairs ahead (support/fetch_ahead.hpp), for stores beyond L2.
struct corner64_method_kernels {
    rect64_indexed_fn indexed_fetching;  ///< 16 pairs ahead into L1: a store beyond L2, within L3
    rect64_indexed_fn indexed_far;       ///< 128 pairs ahead into L2: a store read from DRAM
};

/// The entry points of one backend on double corners, per method that runs
/// there: `exact` and `conservative` decide pair lists fetching nothing ahead
/// (records the caches hold: the scene query's rows, a store within L2); the
/// *_kernels rows fetch ahead.
struct corner64_kernel_table {
    rect64_indexed_fn exact;
    rect64_indexed_fn conservative;
    corner64_method_kernels exact_kernels;
    corner64_method_kernels conservative_kernels;
};

/// The double-corner table of Backend (a SIMD row of dispatch/backend_catalogue.hpp),
/// defined in its per-ISA object (lanes/backend_isa/double_kernels.cpp).
template <class Backend>
const corner64_kernel_table& corner64_kernels_of();

/// The double-corner table of `resolved` (a backend this CPU runs), or nullptr for
/// the scalar backend and for a backend not compiled into this build.
const corner64_kernel_table* corner64_kernels_for(backend resolved);

}  // namespace obbsat::detail
