// Batch collision queries over the double stores (pose_records64, pose_soa64,
// rect_records64): which pairs of rectangles, every double taken exactly,
// collide, as pair lists (collide_pairs) and, on double poses, as streams
// (collide_stream: a[i] against b[i]).
//
// The methods that run on doubles are those with a double reference in
// scalar_ref/: on double poses local, conservative and exact
// (obbsat/ref/local64.hpp, pose_conservative64.hpp, pose_exact64.hpp); on
// double corners conservative and exact (conservative64.hpp, exact64.hpp).
// Any other method is refused with invalid_input naming those that run.
//
// On both double stores every backend runs them, one pair per lane of doubles
// (2 per SSE2 vector, 4 per AVX2, 8 per AVX-512), bit for bit the scalar
// references; options.use picks the backend as for float stores
// (unsupported_backend for one this CPU cannot run). The batch is split over
// options.threads cores, and verdicts never depend on the backend or the
// thread count. Indices are checked
// first (invalid_input naming the first bad pair), and a verdict buffer that
// shares memory with the pairs is refused; nothing is written then. For exact,
// options.slow_path_pairs receives how many pairs the double oracle settled.
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/collide.hpp>
#include <obbsat/method.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/pose_soa64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_records64.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace obbsat {

/// True iff `m` runs on double stores of kind `s`: local on poses;
/// conservative and exact on poses and corners.
bool runs_on_doubles(method m, store_kind s);

/// The methods that run on double stores of kind `s`, in declaration order.
std::vector<method> methods_on_doubles(store_kind s);

/// verdicts[i] = 1 if poses[pairs[i].a] and poses[pairs[i].b] collide, else 0, for
/// i < count; returns the backend that ran. Throws invalid_input (nothing written) as stated above.
backend collide_pairs(const pose_records64& poses, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options);

/// The verdicts of collide_pairs over double poses, one byte (0 or 1) per pair.
std::vector<std::uint8_t> collide_pairs(const pose_records64& poses, const std::vector<pair_index>& pairs,
                                        const collide_options& options);

/// verdicts[i] = 1 if a[i] and b[i] collide, else 0, for i < a.size(): a stream
/// of pairs, the double counterpart of collide_stream over pose_records, on the
/// same lanes as collide_pairs (consecutive records read, no index looked up)
/// and with the same verdicts; returns the backend that ran. Throws
/// invalid_input (nothing written) when a and b differ in length or when
/// options.test does not run on double poses; unsupported_backend as above.
/// `verdicts` holds a.size() bytes.
backend collide_stream(const pose_records64& a, const pose_records64& b, std::uint8_t* verdicts,
                       const collide_options& options);

/// The verdicts of collide_stream over double poses, one byte (0 or 1) per pair.
std::vector<std::uint8_t> collide_stream(const pose_records64& a, const pose_records64& b,
                                         const collide_options& options);

/// The same over two pose_soa64 stores, the faster store for streams (each
/// field read as a vector, nothing transposed); verdicts are identical.
backend collide_stream(const pose_soa64& a, const pose_soa64& b, std::uint8_t* verdicts,
                       const collide_options& options);

/// The verdicts of collide_stream over pose_soa64 stores as a vector.
std::vector<std::uint8_t> collide_stream(const pose_soa64& a, const pose_soa64& b, const collide_options& options);

/// verdicts[i] = 1 if rects[pairs[i].a] and rects[pairs[i].b] collide, else 0, for
/// i < count; returns backend::scalar. Throws invalid_input (nothing written) as stated above.
backend collide_pairs(const rect_records64& rects, const pair_index* pairs, std::size_t count,
                      std::uint8_t* verdicts, const collide_options& options);

/// The verdicts of collide_pairs over double corners, one byte (0 or 1) per pair.
std::vector<std::uint8_t> collide_pairs(const rect_records64& rects, const std::vector<pair_index>& pairs,
                                        const collide_options& options);

}  // namespace obbsat
