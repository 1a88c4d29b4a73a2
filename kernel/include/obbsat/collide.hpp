// Batch collision queries: which pairs of rectangles collide.
//
// These are the checked entry points. They reject out-of-range indices and
// unequal batch lengths with invalid_input (rect_soa already guarantees finite
// coordinates), resolve the backend once per call, and split the batch over
// `threads` cores, or over the caller's executor (obbsat/executor.hpp).
// Verdicts never depend on the backend, the thread count or the executor.
// A pair-list call whose verdict buffer shares memory with its pairs (or with
// the rects or poses it reads in place) throws invalid_input naming both.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/executor.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_soa.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_soa.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat {

struct collide_options {
    method test = method::sat4;           ///< which collision test
    backend use = backend::automatic;     ///< which instruction set (see backend.hpp)
    /// Threads to split one call over; 0 means one per hardware thread. The
    /// steps that split finely cut their work into a few units per thread,
    /// each taken by the next thread free, so a thread on a busy core takes
    /// fewer. With an executor: how many threads its units are cut for.
    unsigned threads = 1;
    /// When set, receives how many pairs were decided on the exact slow path
    /// (method exact only; 0 for the others).
    std::size_t* slow_path_pairs = nullptr;
    /// When set, the engine's job system that runs the call's parallel steps
    /// (obbsat/executor.hpp); the call then starts no thread of its own. It
    /// must outlive the call (for pair_finder, every call). nullptr: obbsat's
    /// own pool of threads.
    const obbsat::executor* executor = nullptr;
};

/// verdicts[i] = 1 if rects[pairs[i].a] and rects[pairs[i].b] collide, else 0,
/// for i < count, over packed records (the fast store for pair lists); returns
/// the backend that ran. Throws invalid_input naming the first pair with an
/// index >= rects.size(), unsupported_backend for a backend this CPU cannot
/// run; nothing is written then.
backend collide_pairs(const rect_records& rects, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options = {});

/// collide_pairs over `rect_count` packed records in the caller's memory
/// (rect_records' layout, 32 bytes each, at least 4-byte aligned), read in
/// place and never kept: for stores owned by another language or a mapped file.
/// Checks every coordinate finite first (one pass over the rectangles), then
/// every index; throws invalid_input naming the first offending rectangle and
/// coordinate, or pair and index; nothing is written then.
backend collide_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs,
                      std::size_t count, std::uint8_t* verdicts, const collide_options& options = {});

/// The verdicts of collide_pairs over packed records, one byte (0 or 1) per pair.
std::vector<std::uint8_t> collide_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options = {});

/// The pairs of `pairs` that collide, in their input order.
std::vector<pair_index> colliding_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options = {});

/// The same over a structure-of-arrays store: each lane gathers its corners
/// from eight arrays (eight cache lines per rectangle), so prefer rect_records
/// for pair lists; verdicts are identical.
/// verdicts[i] = 1 if rects[pairs[i].a] and rects[pairs[i].b] collide, else 0,
/// for i < count; returns the backend that ran. Throws invalid_input naming
/// the first pair with an index >= rects.size(), unsupported_backend for a
/// backend this CPU cannot run; nothing is written then.
backend collide_pairs(const rect_soa& rects, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options = {});

/// The verdicts of collide_pairs as a vector, one byte (0 or 1) per pair.
std::vector<std::uint8_t> collide_pairs(const rect_soa& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options = {});

/// The pairs of `pairs` that collide, in their input order.
std::vector<pair_index> colliding_pairs(const rect_soa& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options = {});

/// verdicts[i] = 1 if a[i] and b[i] collide, else 0, for i < a.size(); returns
/// the backend that ran. Throws invalid_input when a and b differ in size.
backend collide_stream(const rect_soa& a, const rect_soa& b, std::uint8_t* verdicts,
                       const collide_options& options = {});

/// The verdicts of collide_stream as a vector.
std::vector<std::uint8_t> collide_stream(const rect_soa& a, const rect_soa& b,
                                         const collide_options& options = {});

// Poses (pose_records): the methods that run on poses, local, conservative
// and exact (see obbsat/method.hpp), answer for the exact point sets of
// obbsat/rect_pose.hpp. A method that does not run on poses (sat4,
// sat4_centered, sat4_double) is refused with invalid_input; convert with
// corner_records_of (obbsat/pose_conversion.hpp) to run those.

/// verdicts[i] = 1 if poses[pairs[i].a] and poses[pairs[i].b] collide, else 0,
/// for i < count; returns the backend that ran. Throws invalid_input naming the
/// first pair with an index >= poses.size() or a method that does not run on
/// poses, unsupported_backend for a backend this CPU cannot run; nothing is
/// written then.
backend collide_pairs(const pose_records& poses, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options);

/// The same over poses in the caller's memory (24 bytes each, read in place):
/// every pose is checked first (invalid_input naming the first bad pose and
/// field, nothing written), then the two poses of each pair are gathered, a
/// block at a time, into records the method's stream kernel reads. Verdicts
/// are those of collide_pairs over a pose_records of the same poses.
backend collide_pairs(const rect_pose* poses, std::size_t pose_count, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options = {});

/// The verdicts of collide_pairs over poses, one byte (0 or 1) per pair.
std::vector<std::uint8_t> collide_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                        const collide_options& options);

/// The pairs of `pairs` whose poses collide, in their input order.
std::vector<pair_index> colliding_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                        const collide_options& options);

/// verdicts[i] = 1 if a[i] and b[i] collide, else 0, for i < a.size(); returns
/// the backend that ran. Throws invalid_input when a and b differ in size.
backend collide_stream(const pose_records& a, const pose_records& b, std::uint8_t* verdicts,
                       const collide_options& options);

/// The verdicts of collide_stream over poses as a vector.
std::vector<std::uint8_t> collide_stream(const pose_records& a, const pose_records& b,
                                         const collide_options& options);

/// The same over two pose_soa stores, the faster store for streams (each
/// field read as a vector, nothing transposed); verdicts are identical.
backend collide_stream(const pose_soa& a, const pose_soa& b, std::uint8_t* verdicts, const collide_options& options);

/// The verdicts of collide_stream over pose_soa stores as a vector.
std::vector<std::uint8_t> collide_stream(const pose_soa& a, const pose_soa& b, const collide_options& options);

}  // namespace obbsat
