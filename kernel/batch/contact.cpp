// The contact and distance entry points (obbsat/contact.hpp): check the
// input, resolve the backend once, split the pairs over threads, run the
// backend's kernel on each part.
#include "dispatch/backend_registry.hpp"
#include "dispatch/contact_kernel_table.hpp"
#include "store/contact_acceptance.hpp"
#include "store/finite_check.hpp"
#include "support/fetch_ahead.hpp"
#include "support/work_shares.hpp"

#include <obbsat/contact.hpp>
#include <obbsat/error.hpp>
#include <obbsat/ref/contact.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace obbsat {

namespace {

// A contact costs a few tens of nanoseconds: below this many pairs per part,
// waking another core (a few microseconds) costs more than it saves.
constexpr std::size_t min_pairs_per_part = 2048;

// Parts start on multiples of this, so every part but the last fills whole
// vectors of the widest backend.
constexpr std::size_t part_alignment = 64;

constexpr std::size_t pose_row_floats = sizeof(rect_pose) / sizeof(float);
constexpr std::size_t rect_floats = sizeof(rect) / sizeof(float);
static_assert(pose_row_floats == 6 && rect_floats == 8, "rows are packed floats");

/// The pose kernel of `table` for pair lists over a store of `bytes` of
/// records: one that fetches nothing ahead when L2 holds the store.
detail::contact_fn pose_kernel_for_store(const detail::contact_kernel_table& table, std::size_t bytes) {
    return bytes <= detail::store_bytes_in_l2 ? table.poses_in_l2 : table.poses;
}

/// A float as the messages show it: its shortest round-trip-ish decimal form.
std::string shown(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
    return text;
}

void require_margin(const contact_options& options) {
    if (!std::isfinite(options.margin) || !(options.margin >= 0.0f)) {
        throw invalid_input("contact margin is " + shown(options.margin) + ": it must be finite and >= 0");
    }
}

void require_pose_accepted(const rect_pose& p, std::size_t index) {
    if (!ref::pose_accepted(p)) {
        throw invalid_input("pose " + std::to_string(index) + ": rotation (" + shown(p.rotation.x) + ", " +
                            shown(p.rotation.y) +
                            ") is too short or too long for contacts (c*c + s*s must be a normal float)");
    }
}

void require_corners_accepted(const rect& r, std::size_t index) {
    if (!ref::corners_accepted(r)) {
        throw invalid_input("rectangle " + std::to_string(index) +
                            ": corners are not a strictly convex quadrilateral (self-intersecting, degenerate or "
                            "with a reflex corner), which contacts do not accept");
    }
}

/// Throws invalid_input naming the first pair with an index >= rows: one
/// pass of the backend's lanes finds the largest index, and only when it is
/// out of range is the offender searched for.
void require_indices(backend ran, std::size_t rows, const pair_index* pairs, std::size_t count, const char* what) {
    if (count == 0 || detail::kernels_for(ran).largest_index(pairs, count) < rows) {
        return;
    }
    for (std::size_t i = 0; i < count; ++i) {
        const bool a_bad = pairs[i].a >= rows;
        if (a_bad || pairs[i].b >= rows) {
            throw invalid_input("pair " + std::to_string(i) + ": index " +
                                std::to_string(a_bad ? pairs[i].a : pairs[i].b) + " is out of range (" +
                                std::to_string(rows) + " " + what + ")");
        }
    }
}

/// Throws invalid_input when the caller's output (`count` contacts) shares
/// memory with another of its buffers (`bytes` long, named `what`).
void require_out_apart(const contact* out, std::size_t count, const void* other, std::size_t bytes,
                       const char* what) {
    const auto o = reinterpret_cast<std::uintptr_t>(out);
    const auto p = reinterpret_cast<std::uintptr_t>(other);
    if (count != 0 && bytes != 0 && o < p + bytes && p < o + count * sizeof(contact)) {
        throw invalid_input(std::string("contacts and ") + what + " share memory: the output must not overlap " +
                            what);
    }
}

/// Runs kernel(a', b', pairs', n, out') over [0, count) split over `threads`,
/// where a part from `begin` reads the pairs from begin (a pair list) or the
/// records from begin (a stream) and writes out + begin.
template <class Out, class Kernel>
void run_split(const Kernel& kernel, const float* a, std::size_t a_stride, const float* b, std::size_t b_stride,
               const pair_index* pairs, std::size_t count, Out* out, unsigned threads) {
    const std::size_t parts = detail::parts_for(count, threads, min_pairs_per_part);
    detail::run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = detail::aligned_share_of(count, part, parts, part_alignment);
        if (begin < end) {
            if (pairs != nullptr) {
                kernel(a, b, pairs + begin, end - begin, out + begin);
            } else {
                kernel(a + a_stride * begin, b + b_stride * begin, nullptr, end - begin, out + begin);
            }
        }
    });
}

/// run_split of a contact kernel.
void run_split(detail::contact_fn kernel, const float* a, std::size_t a_stride, const float* b,
               std::size_t b_stride, const pair_index* pairs, std::size_t count, contact* out,
               const contact_options& options) {
    run_split(
        [&](const float* pa, const float* pb, const pair_index* pp, std::size_t n, contact* po) {
            kernel(pa, a_stride, pb, b_stride, pp, n, options.margin, po);
        },
        a, a_stride, b, b_stride, pairs, count, out, options.threads);
}

/// run_split of a distance kernel.
void run_split(detail::distance_fn kernel, const float* a, std::size_t a_stride, const float* b,
               std::size_t b_stride, const pair_index* pairs, std::size_t count, closest_points* out,
               const distance_options& options) {
    run_split(
        [&](const float* pa, const float* pb, const pair_index* pp, std::size_t n, closest_points* po) {
            kernel(pa, a_stride, pb, b_stride, pp, n, po);
        },
        a, a_stride, b, b_stride, pairs, count, out, options.threads);
}

/// Throws as require_pose_accepted for the first of `count` poses `Stride`
/// floats apart (c and s at floats 4 and 5).
template <std::size_t Stride>
void require_each_pose_accepted(const float* records, std::size_t count) {
    for (std::size_t row = 0; row < count; ++row) {
        const float* v = records + Stride * row;
        require_pose_accepted(rect_pose{{v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}}, row);
    }
}

/// As require_each_pose_accepted, in one branch-free pass when all are accepted.
void require_rows_accepted(const rect_pose* poses, std::size_t count) {
    const auto* rows = reinterpret_cast<const float*>(poses);
    if (!detail::poses_all_accepted(rows, pose_row_floats, count)) {
        require_each_pose_accepted<pose_row_floats>(rows, count);
    }
}

/// As require_each_pose_accepted for a store, checked in the lanes of `ran`.
void require_poses_accepted(backend ran, const pose_records& poses) {
    if (!detail::contact_kernels_for(ran).poses_accepted(poses.data(), poses.size())) {
        require_each_pose_accepted<pose_records::record_floats>(poses.data(), poses.size());
    }
}

void require_rects_accepted(const rect* rects, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        require_corners_accepted(rects[i], i);
    }
}

void require_same_length(std::size_t a, std::size_t b, const char* what) {
    if (a != b) {
        throw invalid_input("stream batches differ in length: " + std::to_string(a) + " " + what + " in A, " +
                            std::to_string(b) + " in B");
    }
}

}  // namespace

backend contact_pairs(const pose_records& poses, const pair_index* pairs, std::size_t count, contact* out,
                      const contact_options& options) {
    require_out_apart(out, count, pairs, count * sizeof(pair_index), "pairs");
    require_margin(options);
    const backend ran = resolve_backend(options.use);
    require_poses_accepted(ran, poses);
    require_indices(ran, poses.size(), pairs, count, "poses");
    const float* records = poses.data();
    run_split(pose_kernel_for_store(detail::contact_kernels_for(ran), poses.size() * sizeof(float) *
                                                                          pose_records::record_floats),
              records, pose_records::record_floats, records,
              pose_records::record_floats, pairs, count, out, options);
    return ran;
}

backend contact_pairs(const rect_pose* poses, std::size_t pose_count, const pair_index* pairs, std::size_t count,
                      contact* out, const contact_options& options) {
    require_out_apart(out, count, pairs, count * sizeof(pair_index), "pairs");
    require_out_apart(out, count, poses, pose_count * sizeof(rect_pose), "poses");
    require_margin(options);
    const backend ran = resolve_backend(options.use);
    require_valid_poses(poses, pose_count);
    require_rows_accepted(poses, pose_count);
    require_indices(ran, pose_count, pairs, count, "poses");
    const auto* rows = reinterpret_cast<const float*>(poses);
    run_split(pose_kernel_for_store(detail::contact_kernels_for(ran), pose_count * sizeof(rect_pose)), rows,
              pose_row_floats, rows, pose_row_floats, pairs, count,
              out, options);
    return ran;
}

std::vector<contact> contact_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                   const contact_options& options) {
    std::vector<contact> out(pairs.size());
    contact_pairs(poses, pairs.data(), pairs.size(), out.data(), options);
    return out;
}

backend contact_stream(const pose_records& a, const pose_records& b, contact* out,
                       const contact_options& options) {
    require_same_length(a.size(), b.size(), "poses");
    require_margin(options);
    const backend ran = resolve_backend(options.use);
    require_poses_accepted(ran, a);
    require_poses_accepted(ran, b);
    run_split(detail::contact_kernels_for(ran).poses, a.data(), pose_records::record_floats, b.data(),
              pose_records::record_floats, nullptr, a.size(), out, options);
    return ran;
}

std::vector<contact> contact_stream(const pose_records& a, const pose_records& b, const contact_options& options) {
    std::vector<contact> out(a.size());
    contact_stream(a, b, out.data(), options);
    return out;
}

backend contact_pairs(const rect_records& rects, const pair_index* pairs, std::size_t count, contact* out,
                      const contact_options& options) {
    require_out_apart(out, count, pairs, count * sizeof(pair_index), "pairs");
    require_margin(options);
    const backend ran = resolve_backend(options.use);
    require_rects_accepted(rects.data(), rects.size());
    require_indices(ran, rects.size(), pairs, count, "rectangles");
    const auto* records = reinterpret_cast<const float*>(rects.data());
    run_split(detail::contact_kernels_for(ran).corners, records, rect_floats, records, rect_floats, pairs, count,
              out, options);
    return ran;
}

backend contact_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs, std::size_t count,
                      contact* out, const contact_options& options) {
    require_out_apart(out, count, pairs, count * sizeof(pair_index), "pairs");
    require_out_apart(out, count, rects, rect_count * sizeof(rect), "rects");
    require_margin(options);
    const backend ran = resolve_backend(options.use);
    for (std::size_t i = 0; i < rect_count; ++i) {
        detail::require_finite(rects[i], i);
    }
    require_rects_accepted(rects, rect_count);
    require_indices(ran, rect_count, pairs, count, "rectangles");
    const auto* rows = reinterpret_cast<const float*>(rects);
    run_split(detail::contact_kernels_for(ran).corners, rows, rect_floats, rows, rect_floats, pairs, count, out,
              options);
    return ran;
}

std::vector<contact> contact_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                   const contact_options& options) {
    std::vector<contact> out(pairs.size());
    contact_pairs(rects, pairs.data(), pairs.size(), out.data(), options);
    return out;
}

backend contact_stream(const rect_records& a, const rect_records& b, contact* out,
                       const contact_options& options) {
    require_same_length(a.size(), b.size(), "rectangles");
    require_margin(options);
    const backend ran = resolve_backend(options.use);
    require_rects_accepted(a.data(), a.size());
    require_rects_accepted(b.data(), b.size());
    run_split(detail::contact_kernels_for(ran).corners, reinterpret_cast<const float*>(a.data()), rect_floats,
              reinterpret_cast<const float*>(b.data()), rect_floats, nullptr, a.size(), out, options);
    return ran;
}

namespace {

/// Throws invalid_input when the caller's output (`count` results) shares
/// memory with the pairs.
void require_distances_apart(const closest_points* out, std::size_t count, const pair_index* pairs) {
    const auto o = reinterpret_cast<std::uintptr_t>(out);
    const auto p = reinterpret_cast<std::uintptr_t>(pairs);
    if (count != 0 && o < p + count * sizeof(pair_index) && p < o + count * sizeof(closest_points)) {
        throw invalid_input("distances and pairs share memory: the output must not overlap pairs");
    }
}

}  // namespace

backend distance_pairs(const pose_records& poses, const pair_index* pairs, std::size_t count, closest_points* out,
                       const distance_options& options) {
    require_distances_apart(out, count, pairs);
    const backend ran = resolve_backend(options.use);
    require_poses_accepted(ran, poses);
    require_indices(ran, poses.size(), pairs, count, "poses");
    const float* records = poses.data();
    run_split(detail::contact_kernels_for(ran).distance_poses, records, pose_records::record_floats, records,
              pose_records::record_floats, pairs, count, out, options);
    return ran;
}

std::vector<closest_points> distance_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                           const distance_options& options) {
    std::vector<closest_points> out(pairs.size());
    distance_pairs(poses, pairs.data(), pairs.size(), out.data(), options);
    return out;
}

backend distance_stream(const pose_records& a, const pose_records& b, closest_points* out,
                        const distance_options& options) {
    require_same_length(a.size(), b.size(), "poses");
    const backend ran = resolve_backend(options.use);
    require_poses_accepted(ran, a);
    require_poses_accepted(ran, b);
    run_split(detail::contact_kernels_for(ran).distance_poses, a.data(), pose_records::record_floats, b.data(),
              pose_records::record_floats, nullptr, a.size(), out, options);
    return ran;
}

backend distance_pairs(const rect_records& rects, const pair_index* pairs, std::size_t count, closest_points* out,
                       const distance_options& options) {
    require_distances_apart(out, count, pairs);
    const backend ran = resolve_backend(options.use);
    require_rects_accepted(rects.data(), rects.size());
    require_indices(ran, rects.size(), pairs, count, "rectangles");
    const auto* records = reinterpret_cast<const float*>(rects.data());
    run_split(detail::contact_kernels_for(ran).distance_corners, records, rect_floats, records, rect_floats, pairs,
              count, out, options);
    return ran;
}

std::vector<closest_points> distance_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                           const distance_options& options) {
    std::vector<closest_points> out(pairs.size());
    distance_pairs(rects, pairs.data(), pairs.size(), out.data(), options);
    return out;
}

backend distance_stream(const rect_records& a, const rect_records& b, closest_points* out,
                        const distance_options& options) {
    require_same_length(a.size(), b.size(), "rectangles");
    const backend ran = resolve_backend(options.use);
    require_rects_accepted(a.data(), a.size());
    require_rects_accepted(b.data(), b.size());
    run_split(detail::contact_kernels_for(ran).distance_corners, reinterpret_cast<const float*>(a.data()),
              rect_floats, reinterpret_cast<const float*>(b.data()), rect_floats, nullptr, a.size(), out, options);
    return ran;
}

}  // namespace obbsat
