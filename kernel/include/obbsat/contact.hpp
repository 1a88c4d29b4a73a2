// Contacts of colliding pairs: for each pair (A, B) of boxes, the unit normal
// from A to B, the penetration depth along it, and a manifold of up to two
// points with feature keys (obbsat/contact_manifold.hpp), as a physics solver
// needs them, computed as the scalar reference obbsat/ref/contact.hpp states,
// bit for bit the same on every backend and thread count.
//
// The entry points mirror collide_pairs and collide_stream (obbsat/collide.hpp):
// a pair list (indexed rows) or a stream (a[i] against b[i]), on poses or on
// corners. They check everything first and throw invalid_input naming the row
// and field, or the pair and index, at fault; nothing is written then.
//
// Poses: any valid pose (obbsat/rect_pose.hpp), zero half extents included;
// the rotation vector's squared length c·c + s·s must be a normal float
// (about 1e-19 to 1e19 long), as the normals are divided by its root.
//
// Corners: the quad must be strictly convex in either winding: its four turns
// cross(e[k], e[k+1]) all > 0 or all < 0 in float32, with edges
// e[k] = corner k+1 − corner k, and no edge of zero (or overflowing) squared
// length. A quad that is not a rectangle but passes is taken as the convex
// polygon of its four edges, with its edges' outward normals; a self-
// intersecting, degenerate (two equal corners, three on a line) or reflex
// quad is rejected with invalid_input naming the rectangle. Hold such shapes
// as poses instead (a pose with a zero half extent is a segment or a point).
#pragma once

#include <obbsat/backend.hpp>
#include <obbsat/closest_points.hpp>
#include <obbsat/contact_manifold.hpp>
#include <obbsat/pose_records.hpp>
#include <obbsat/pose_records64.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_records.hpp>
#include <obbsat/rect_records64.hpp>

#include <cstddef>
#include <vector>

namespace obbsat {

struct contact_options {
    backend use = backend::automatic;  ///< which instruction set (see backend.hpp)
    unsigned threads = 1;              ///< cores to split one batch over; 0 means all
    /// Speculative margin (finite, >= 0): pairs apart by at most this much
    /// along the reference normal get their points too, with separations up
    /// to the margin; 0 gives points to overlapping and touching pairs only.
    float margin = 0.0f;
};

/// out[i] = the contact of poses[pairs[i].a] and poses[pairs[i].b] for i < count;
/// returns the backend that ran. Throws invalid_input for a bad margin, a pose
/// whose rotation is too short or too long, or the first pair with an index
/// >= poses.size(); unsupported_backend for a backend this CPU cannot run.
backend contact_pairs(const pose_records& poses, const pair_index* pairs, std::size_t count, contact* out,
                      const contact_options& options = {});

/// The same over `pose_count` pose rows in the caller's memory, read in place:
/// every pose is checked first (invalid_input naming the pose and field).
backend contact_pairs(const rect_pose* poses, std::size_t pose_count, const pair_index* pairs, std::size_t count,
                      contact* out, const contact_options& options = {});

/// The contacts of contact_pairs over poses, one per pair.
std::vector<contact> contact_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                   const contact_options& options = {});

/// out[i] = the contact of a[i] and b[i] for i < a.size(); throws invalid_input
/// when a and b differ in size, and as contact_pairs.
backend contact_stream(const pose_records& a, const pose_records& b, contact* out,
                       const contact_options& options = {});

/// The contacts of contact_stream over poses.
std::vector<contact> contact_stream(const pose_records& a, const pose_records& b,
                                    const contact_options& options = {});

/// out[i] = the contact of the corner quads rects[pairs[i].a] and
/// rects[pairs[i].b] for i < count; returns the backend that ran. Throws
/// invalid_input for a bad margin, the first quad that is not strictly convex
/// (see above) or the first pair with an index >= rects.size().
backend contact_pairs(const rect_records& rects, const pair_index* pairs, std::size_t count, contact* out,
                      const contact_options& options = {});

/// The same over `rect_count` corner rows in the caller's memory, read in
/// place: every coordinate is checked finite first, then every quad convex.
backend contact_pairs(const rect* rects, std::size_t rect_count, const pair_index* pairs, std::size_t count,
                      contact* out, const contact_options& options = {});

/// The contacts of contact_pairs over corner records, one per pair.
std::vector<contact> contact_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                   const contact_options& options = {});

/// out[i] = the contact of the corner quads a[i] and b[i] for i < a.size().
backend contact_stream(const rect_records& a, const rect_records& b, contact* out,
                       const contact_options& options = {});

// Distances of separated pairs (obbsat/ref/distance.hpp): the Euclidean
// distance between the closed boxes and a point of each at that distance;
// all zero for a pair that collides. The same store rules and checks as
// contacts.

struct distance_options {
    backend use = backend::automatic;  ///< which instruction set (see backend.hpp)
    unsigned threads = 1;              ///< cores to split one batch over; 0 means all
};

/// out[i] = the distance and closest points of poses[pairs[i].a] and
/// poses[pairs[i].b] for i < count; returns the backend that ran. Throws as
/// contact_pairs over poses.
backend distance_pairs(const pose_records& poses, const pair_index* pairs, std::size_t count, closest_points* out,
                       const distance_options& options = {});

/// The distances of distance_pairs over poses, one per pair.
std::vector<closest_points> distance_pairs(const pose_records& poses, const std::vector<pair_index>& pairs,
                                           const distance_options& options = {});

/// out[i] = the distance and closest points of a[i] and b[i] for i < a.size().
backend distance_stream(const pose_records& a, const pose_records& b, closest_points* out,
                        const distance_options& options = {});

/// out[i] = the distance and closest points of the corner quads rects[pairs[i].a]
/// and rects[pairs[i].b]; throws as contact_pairs over corners.
backend distance_pairs(const rect_records& rects, const pair_index* pairs, std::size_t count, closest_points* out,
                       const distance_options& options = {});

/// The distances of distance_pairs over corner records, one per pair.
std::vector<closest_points> distance_pairs(const rect_records& rects, const std::vector<pair_index>& pairs,
                                           const distance_options& options = {});

/// out[i] = the distance and closest points of the corner quads a[i] and b[i].
backend distance_stream(const rect_records& a, const rect_records& b, closest_points* out,
                        const distance_options& options = {});

// Contacts and distances of double boxes (pose_records64, rect_records64):
// the same steps computed in double (obbsat/ref/contact.hpp and distance.hpp
// state it), every double of the input taken as it is, nothing rounded to
// float32. The same rules and checks as the float entry points, read in
// double: a pose's c·c + s·s must be a normal double, a quad strictly convex
// in double, the margin finite and >= 0.
//
// Double contacts and distances run on every backend, as the float ones (the
// SIMD lanes compute the double references' operations in their order), split
// over options.threads cores; the results never depend on the backend or the
// thread count.

struct contact_options64 {
    backend use = backend::automatic;  ///< the backend, as contact_options.use
    unsigned threads = 1;              ///< cores to split one batch over; 0 means all
    /// Speculative margin (finite, >= 0), as contact_options.margin, in double.
    double margin = 0.0;
};

/// out[i] = the contact of poses[pairs[i].a] and poses[pairs[i].b] in double
/// for i < count; returns the backend that ran. Throws invalid_input for a bad
/// margin, a backend this CPU cannot run, a pose whose rotation is too short or too long, the
/// first pair with an index >= poses.size(), or an output that overlaps the pairs.
backend contact_pairs(const pose_records64& poses, const pair_index* pairs, std::size_t count, contact64* out,
                      const contact_options64& options = {});

/// The contacts of contact_pairs over double poses, one per pair.
std::vector<contact64> contact_pairs(const pose_records64& poses, const std::vector<pair_index>& pairs,
                                     const contact_options64& options = {});

/// out[i] = the contact of the double corner quads rects[pairs[i].a] and
/// rects[pairs[i].b] for i < count; throws as contact_pairs over double poses,
/// with the first quad that is not strictly convex in place of a bad pose.
backend contact_pairs(const rect_records64& rects, const pair_index* pairs, std::size_t count, contact64* out,
                      const contact_options64& options = {});

/// The contacts of contact_pairs over double corners, one per pair.
std::vector<contact64> contact_pairs(const rect_records64& rects, const std::vector<pair_index>& pairs,
                                     const contact_options64& options = {});

/// out[i] = the contact of a[i] and b[i] in double for i < a.size(); throws
/// invalid_input when a and b differ in size, and as contact_pairs.
backend contact_stream(const pose_records64& a, const pose_records64& b, contact64* out,
                       const contact_options64& options = {});

/// out[i] = the contact of the double corner quads a[i] and b[i] for i < a.size().
backend contact_stream(const rect_records64& a, const rect_records64& b, contact64* out,
                       const contact_options64& options = {});

/// out[i] = the distance and closest points of double poses[pairs[i].a] and
/// poses[pairs[i].b] for i < count, in double; returns the backend that ran. Throws
/// as contact_pairs over double poses (there is no margin).
backend distance_pairs(const pose_records64& poses, const pair_index* pairs, std::size_t count,
                       closest_points64* out, const distance_options& options = {});

/// The distances of distance_pairs over double poses, one per pair.
std::vector<closest_points64> distance_pairs(const pose_records64& poses, const std::vector<pair_index>& pairs,
                                             const distance_options& options = {});

/// out[i] = the distance and closest points of the double corner quads
/// rects[pairs[i].a] and rects[pairs[i].b], in double; throws as contact_pairs
/// over double corners.
backend distance_pairs(const rect_records64& rects, const pair_index* pairs, std::size_t count,
                       closest_points64* out, const distance_options& options = {});

/// The distances of distance_pairs over double corners, one per pair.
std::vector<closest_points64> distance_pairs(const rect_records64& rects, const std::vector<pair_index>& pairs,
                                             const distance_options& options = {});

/// out[i] = the distance and closest points of double poses a[i] and b[i], in double.
backend distance_stream(const pose_records64& a, const pose_records64& b, closest_points64* out,
                        const distance_options& options = {});

/// out[i] = the distance and closest points of double corner quads a[i] and b[i], in double.
backend distance_stream(const rect_records64& a, const rect_records64& b, closest_points64* out,
                        const distance_options& options = {});

}  // namespace obbsat
