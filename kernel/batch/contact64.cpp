// The contact and distance entry points over the double stores
// (obbsat/contact.hpp, the *64 overloads): check everything first, then run
// the backend's double kernel (lanes bit for bit the double references,
// obbsat/ref/contact.hpp and distance.hpp; the references themselves on the
// scalar backend), the pairs split over threads.
#include "dispatch/backend_registry.hpp"
#include "dispatch/contact_kernel_table.hpp"
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

// A double contact costs a few tens of nanoseconds: below this many pairs per
// part, waking another core costs more than it saves.
constexpr std::size_t min_pairs_per_part = 2048;

// Parts start on multiples of this, so every part but the last fills whole
// vectors of the widest backend.
constexpr std::size_t part_alignment = 64;

constexpr std::size_t record_doubles = 8;
static_assert(sizeof(rect64) == record_doubles * sizeof(double) &&
                  pose_records64::record_doubles == record_doubles,
              "both double stores hold records of eight doubles");

/// A double as the messages show it, read back to the same value.
std::string shown(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

void require_margin(double margin) {
    if (!std::isfinite(margin) || !(margin >= 0.0)) {
        throw invalid_input("contact margin is " + shown(margin) + ": it must be finite and >= 0");
    }
}

/// Throws invalid_input when the output (`out_bytes` long) shares memory with the pairs.
void require_out_apart(const void* out, std::size_t out_bytes, const pair_index* pairs, std::size_t count,
                       const char* what) {
    const auto o = reinterpret_cast<std::uintptr_t>(out);
    const auto p = reinterpret_cast<std::uintptr_t>(pairs);
    if (count != 0 && o < p + count * sizeof(pair_index) && p < o + out_bytes) {
        throw invalid_input(std::string(what) + " and pairs share memory: the output must not overlap pairs");
    }
}

/// Throws invalid_input naming the first pair with an index >= rows: one
/// pass of the backend's lanes finds the largest index, and only when it is
/// out of range is the offender searched for.
void require_indices(backend ran, std::size_t rows, const pair_index* pairs, std::size_t count,
                     const char* rows_name) {
    if (count == 0 || detail::kernels_for(ran).largest_index(pairs, count) < rows) {
        return;
    }
    for (std::size_t i = 0; i < count; ++i) {
        const bool a_bad = pairs[i].a >= rows;
        if (a_bad || pairs[i].b >= rows) {
            throw invalid_input("pair " + std::to_string(i) + ": index " +
                                std::to_string(a_bad ? pairs[i].a : pairs[i].b) + " is out of range (" +
                                std::to_string(rows) + " " + rows_name + ")");
        }
    }
}

void require_accepted(backend ran, const pose_records64& poses) {
    if (detail::contact_kernels_for(ran).poses64_accepted(poses.data(), poses.size())) {
        return;
    }
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const rect_pose64 p = poses[i];
        if (!ref::pose_accepted(p)) {
            throw invalid_input("pose " + std::to_string(i) + ": rotation (" + shown(p.rotation.x) + ", " +
                                shown(p.rotation.y) +
                                ") is too short or too long for contacts (c*c + s*s must be a normal double)");
        }
    }
}

void require_accepted(backend, const rect_records64& rects) {
    for (std::size_t i = 0; i < rects.size(); ++i) {
        if (!ref::corners_accepted(rects[i])) {
            throw invalid_input("rectangle " + std::to_string(i) +
                                ": corners are not a strictly convex quadrilateral (self-intersecting, degenerate "
                                "or with a reflex corner), which contacts do not accept");
        }
    }
}

const char* rows_name(const pose_records64&) { return "poses"; }
const char* rows_name(const rect_records64&) { return "rectangles"; }

/// The checks of every double entry point, in order, before anything is
/// written: the output apart from the pairs, the backend (resolved, which
/// refuses one this CPU lacks), every box, every index. Returns the backend.
template <class Store, class Out>
backend require_call(const Store& store, const pair_index* pairs, std::size_t count, const Out* out, backend use,
                     const char* what) {
    require_out_apart(out, count * sizeof(Out), pairs, count, what);
    const backend ran = resolve_backend(use);
    require_accepted(ran, store);
    require_indices(ran, store.size(), pairs, count, rows_name(store));
    return ran;
}

void require_same_length(std::size_t a, std::size_t b, const char* rows) {
    if (a != b) {
        throw invalid_input("stream batches differ in length: " + std::to_string(a) + " " + rows + " in A, " +
                            std::to_string(b) + " " + rows + " in B");
    }
}

/// The checks of a stream entry point, before anything is written; returns the backend.
template <class Store>
backend require_stream(const Store& a, const Store& b, backend use) {
    require_same_length(a.size(), b.size(), rows_name(a));
    const backend ran = resolve_backend(use);
    require_accepted(ran, a);
    require_accepted(ran, b);
    return ran;
}

const double* records_of(const pose_records64& poses) { return poses.data(); }
const double* records_of(const rect_records64& rects) { return reinterpret_cast<const double*>(rects.data()); }

/// The contact kernel of `table` for a store: for a pair list over poses L2
/// holds, the one that fetches nothing ahead.
detail::contact64_fn contact_kernel_for(const detail::contact_kernel_table& table, const pose_records64& poses,
                                        bool listed) {
    const bool in_l2 = listed && poses.size() * sizeof(double) * record_doubles <= detail::store_bytes_in_l2;
    return in_l2 ? table.poses64_in_l2 : table.poses64;
}

detail::contact64_fn contact_kernel_for(const detail::contact_kernel_table& table, const rect_records64&, bool) {
    return table.corners64;
}

detail::distance64_fn distance_kernel_for(const detail::contact_kernel_table& table, const pose_records64&) {
    return table.distance_poses64;
}

detail::distance64_fn distance_kernel_for(const detail::contact_kernel_table& table, const rect_records64&) {
    return table.distance_corners64;
}

/// run(a', b', pairs', n, out') over [0, count) split over `threads` into
/// parts of whole vectors, where a part from `begin` reads the pairs from
/// begin (a pair list) or the records of a and b from begin (a stream) and
/// writes out + begin.
template <class Store, class Out, class Run>
void run_split(const Store& a, const Store& b, const pair_index* pairs, std::size_t count, Out* out,
               unsigned threads, const Run& run) {
    const double* ra = records_of(a);
    const double* rb = records_of(b);
    const std::size_t parts = detail::parts_for(count, threads, min_pairs_per_part);
    detail::run_parts(parts, [&](std::size_t part) {
        const auto [begin, end] = detail::aligned_share_of(count, part, parts, part_alignment);
        if (begin < end) {
            if (pairs != nullptr) {
                run(ra, rb, pairs + begin, end - begin, out + begin);
            } else {
                run(ra + record_doubles * begin, rb + record_doubles * begin, nullptr, end - begin, out + begin);
            }
        }
    });
}

/// out[i] = the contact of a(pairs[i].a) and b(pairs[i].b), or of a(i) and
/// b(i) without pairs, by the kernel of backend `ran`.
template <class Store>
void run_contacts(backend ran, const Store& a, const Store& b, const pair_index* pairs, std::size_t count,
                  contact64* out, const contact_options64& options) {
    const detail::contact64_fn kernel = contact_kernel_for(detail::contact_kernels_for(ran), a, pairs != nullptr);
    run_split(a, b, pairs, count, out, options.threads,
              [&](const double* pa, const double* pb, const pair_index* pp, std::size_t n, contact64* po) {
                  kernel(pa, record_doubles, pb, record_doubles, pp, n, options.margin, po);
              });
}

/// out[i] = the distance of a(pairs[i].a) and b(pairs[i].b), or of a(i) and
/// b(i) without pairs, by the kernel of backend `ran`.
template <class Store>
void run_distances(backend ran, const Store& a, const Store& b, const pair_index* pairs, std::size_t count,
                   closest_points64* out, const distance_options& options) {
    const detail::distance64_fn kernel = distance_kernel_for(detail::contact_kernels_for(ran), a);
    run_split(a, b, pairs, count, out, options.threads,
              [&](const double* pa, const double* pb, const pair_index* pp, std::size_t n, closest_points64* po) {
                  kernel(pa, record_doubles, pb, record_doubles, pp, n, po);
              });
}

template <class Store>
backend contacts_of(const Store& store, const pair_index* pairs, std::size_t count, contact64* out,
                    const contact_options64& options) {
    require_margin(options.margin);
    const backend ran = require_call(store, pairs, count, out, options.use, "contacts");
    run_contacts(ran, store, store, pairs, count, out, options);
    return ran;
}

template <class Store>
backend distances_of(const Store& store, const pair_index* pairs, std::size_t count, closest_points64* out,
                     const distance_options& options) {
    const backend ran = require_call(store, pairs, count, out, options.use, "distances");
    run_distances(ran, store, store, pairs, count, out, options);
    return ran;
}

template <class Store>
backend contact_stream_of(const Store& a, const Store& b, contact64* out, const contact_options64& options) {
    require_margin(options.margin);
    const backend ran = require_stream(a, b, options.use);
    run_contacts(ran, a, b, nullptr, a.size(), out, options);
    return ran;
}

template <class Store>
backend distance_stream_of(const Store& a, const Store& b, closest_points64* out, const distance_options& options) {
    const backend ran = require_stream(a, b, options.use);
    run_distances(ran, a, b, nullptr, a.size(), out, options);
    return ran;
}

template <class Out, class Store, class Options, class Run>
std::vector<Out> collected(const Store& store, const std::vector<pair_index>& pairs, const Options& options,
                           const Run& run) {
    std::vector<Out> out(pairs.size());
    run(store, pairs.data(), pairs.size(), out.data(), options);
    return out;
}

}  // namespace

backend contact_pairs(const pose_records64& poses, const pair_index* pairs, std::size_t count, contact64* out,
                      const contact_options64& options) {
    return contacts_of(poses, pairs, count, out, options);
}

std::vector<contact64> contact_pairs(const pose_records64& poses, const std::vector<pair_index>& pairs,
                                     const contact_options64& options) {
    return collected<contact64>(poses, pairs, options, contacts_of<pose_records64>);
}

backend contact_pairs(const rect_records64& rects, const pair_index* pairs, std::size_t count, contact64* out,
                      const contact_options64& options) {
    return contacts_of(rects, pairs, count, out, options);
}

std::vector<contact64> contact_pairs(const rect_records64& rects, const std::vector<pair_index>& pairs,
                                     const contact_options64& options) {
    return collected<contact64>(rects, pairs, options, contacts_of<rect_records64>);
}

backend distance_pairs(const pose_records64& poses, const pair_index* pairs, std::size_t count,
                       closest_points64* out, const distance_options& options) {
    return distances_of(poses, pairs, count, out, options);
}

std::vector<closest_points64> distance_pairs(const pose_records64& poses, const std::vector<pair_index>& pairs,
                                             const distance_options& options) {
    return collected<closest_points64>(poses, pairs, options, distances_of<pose_records64>);
}

backend distance_pairs(const rect_records64& rects, const pair_index* pairs, std::size_t count,
                       closest_points64* out, const distance_options& options) {
    return distances_of(rects, pairs, count, out, options);
}

std::vector<closest_points64> distance_pairs(const rect_records64& rects, const std::vector<pair_index>& pairs,
                                             const distance_options& options) {
    return collected<closest_points64>(rects, pairs, options, distances_of<rect_records64>);
}

backend contact_stream(const pose_records64& a, const pose_records64& b, contact64* out,
                       const contact_options64& options) {
    return contact_stream_of(a, b, out, options);
}

backend contact_stream(const rect_records64& a, const rect_records64& b, contact64* out,
                       const contact_options64& options) {
    return contact_stream_of(a, b, out, options);
}

backend distance_stream(const pose_records64& a, const pose_records64& b, closest_points64* out,
                        const distance_options& options) {
    return distance_stream_of(a, b, out, options);
}

backend distance_stream(const rect_records64& a, const rect_records64& b, closest_points64* out,
                        const distance_options& options) {
    return distance_stream_of(a, b, out, options);
}

}  // namespace obbsat
