// The contact and distance entry points of one backend (obbsat/contact.hpp),
// a table of their own beside kernel_table. The per-ISA kernels include this header: it
// holds only types and declarations (kernel/lanes/README.md).
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/closest_points.hpp>
#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect.hpp>

#include <cstddef>

namespace obbsat::detail {

/// out[i] = ref::contact_of(box a(i), box b(i), margin) for i < count, where a
/// box is read from the record at a + a_stride·index (in floats), and likewise b:
/// with pairs, a(i) = pairs[i].a and b(i) = pairs[i].b (every index in range,
/// the caller checks); without (nullptr), a(i) = b(i) = i.
using contact_fn = void (*)(const float* a, std::size_t a_stride, const float* b, std::size_t b_stride,
                            const pair_index* pairs, std::size_t count, float margin, contact* out);

/// As contact_fn on double records (pose_records64, rect_records64: eight
/// doubles each, strides in doubles) and double contacts.
using contact64_fn = void (*)(const double* a, std::size_t a_stride, const double* b, std::size_t b_stride,
                              const pair_index* pairs, std::size_t count, double margin, contact64* out);

/// out[i] = ref::distance_of(box a(i), box b(i)) for i < count, records read as contact_fn reads them.
using distance_fn = void (*)(const float* a, std::size_t a_stride, const float* b, std::size_t b_stride,
                             const pair_index* pairs, std::size_t count, closest_points* out);

/// As distance_fn on double records (read as contact64_fn reads them) and double results.
using distance64_fn = void (*)(const double* a, std::size_t a_stride, const double* b, std::size_t b_stride,
                               const pair_index* pairs, std::size_t count, closest_points64* out);

/// Whether every one of `count` pose_records records (cx, cy, hx, hy, c, s,
/// 0, 0; every value finite) is ref::pose_accepted: c·c + s·s a normal float.
using poses_accepted_fn = bool (*)(const float* records, std::size_t count);

/// As poses_accepted_fn on pose_records64 records, in double.
using poses64_accepted_fn = bool (*)(const double* records, std::size_t count);

struct contact_kernel_table {
    /// Records of at least six floats: cx, cy, hx, hy, c, s; with pairs, the
    /// records of the pairs ahead are asked into L2.
    contact_fn poses;
    /// As poses, for a store L2 holds (fetch_ahead.hpp's store_bytes_in_l2):
    /// nothing is asked for ahead.
    contact_fn poses_in_l2;
    contact_fn corners;  ///< records of eight floats: the corners UL, UR, LR, LL
    distance_fn distance_poses;
    distance_fn distance_corners;
    /// pose_records64 records (cx, cy, hx, hy, c, s, 0, 0); with pairs, the
    /// records of the pairs ahead are asked into L2.
    contact64_fn poses64;
    contact64_fn poses64_in_l2;  ///< as poses64, for a store L2 holds
    contact64_fn corners64;      ///< rect_records64 records: the corners UL, UR, LR, LL
    distance64_fn distance_poses64;
    distance64_fn distance_corners64;
    poses_accepted_fn poses_accepted;      ///< the check of a pose_records store before its contacts
    poses64_accepted_fn poses64_accepted;  ///< the check of a pose_records64 store before its contacts
};

/// The contact table of one backend of backend_catalogue.hpp: defined by
/// scalar_contact_kernels.cpp for the scalar path and by
/// lanes/backend_isa/contact_kernels.cpp once per SIMD instruction set.
template <class Backend>
const contact_kernel_table& contact_kernels_of();

/// The contact table of `resolved`, which resolve_backend has already checked.
const contact_kernel_table& contact_kernels_for(backend resolved);

}  // namespace obbsat::detail
