// The contacts of every colliding pair of a scene, with no pair list to
// bring: the scene query (obbsat/find_pairs.hpp) finds the pairs, and each
// pair's contact is computed as the pair is found, on the rows the query has
// just tested (the contact entry points' kernels, obbsat/contact.hpp, so bit
// for bit contact_pairs' contacts); both come back together, sorted by
// (i, j). A frame of a pair_finder with contacts: pair_finder::find_contacts.
//
// Memory: the contacts are written into blocks that the library keeps from
// one call to the next (about 60 bytes per pair of the largest answer so
// far, for the life of the process), so that a call writes no fresh memory
// beside its answer; a call made while another thread's call holds them
// makes blocks of its own, dropped when it returns.
//
// Which pairs are reported:
//   - margin 0: exactly the pairs of find_pairs(boxes, options), each with
//     its contact (a pair the method calls colliding may come back with no
//     points when the contact's float steps see it apart, and is kept);
//   - margin > 0: those pairs, and every other pair whose contact with that
//     margin has at least one point (apart by at most the margin).
//
// Why widened bounds find every pair within the margin: a contact point is a
// point of the incident box, clipped to the reference face's side planes, at
// a separation s <= margin from the face, so the two boxes are within
// max(s, 0) <= margin of each other and their bounds at most margin apart.
// The candidates are therefore the pairs of axis-aligned stand-ins, one per
// box, that contain its bounds (obbsat/ref/bounds.hpp) widened by the whole
// margin on every side (twice what is needed, so float rounding in building
// them never loses a pair), found by method exact; the contacts of the
// candidates decide which stay.
//
// Double rows (box_view::precision() float64: rect_pose64, rect64 and their
// stores): find_contacts64, or find_contacts into a scene_contacts64, gives
// each pair's contact in double (contact64, obbsat/contact.hpp's double
// contacts: bit for bit contact_pairs over the same double rows and pairs,
// on every backend and thread count); nothing is rounded to float32. The
// pairs are those of find_pairs on the double rows (its methods on doubles,
// obbsat/collide64.hpp), and with a margin (a double, finite and >= 0) every
// other pair whose double contact with that margin has a point, by the
// argument above on the double bounds (obbsat/ref/bounds64.hpp, rounded
// outward to float, then widened). The float calls (scene_contacts) refuse
// double rows, and the double calls float rows, with invalid_input: a
// contact is never rounded on the way. Rows of rect_pose64 (six doubles) are
// copied into 64-byte records for the double kernels (64 bytes per box,
// kept for the next call as the margin's memory is); stores and rect64 rows
// are read in place.
#pragma once

#include <obbsat/contact.hpp>
#include <obbsat/find_pairs.hpp>

#include <vector>

namespace obbsat {

/// The pairs of a scene with their contacts: contacts[k] is the contact of
/// pairs[k], with A = boxes[pairs[k].a] and B = boxes[pairs[k].b], a < b.
struct scene_contacts {
    std::vector<pair_index> pairs;  ///< sorted by a, then b
    std::vector<contact> contacts;  ///< one per pair
};

/// The pairs of a scene of double rows with their double contacts: as
/// scene_contacts, contacts[k] the contact64 of pairs[k].
struct scene_contacts64 {
    std::vector<pair_index> pairs;    ///< sorted by a, then b
    std::vector<contact64> contacts;  ///< one per pair
};

/// Every pair (i, j), i < j, of `boxes` that collides under options.test or,
/// with margin > 0, is within the margin (see above), and its contact on
/// options.use with options.threads. Throws invalid_input for an invalid box
/// (as find_pairs), a margin that is negative or not finite, and, on
/// corners, a quad that is not strictly convex (as contact_pairs);
/// unsupported_backend for a backend this CPU lacks. Pair filters carried by
/// `boxes` apply to both kinds of pair. Float rows only: double rows are
/// refused with invalid_input (their contacts: find_contacts64).
scene_contacts find_contacts(box_view boxes, const collide_options& options, float margin = 0.0f);

/// The same into `found`, whose vectors keep their memory from one call to
/// the next: a caller that finds contacts every step writes no fresh memory
/// once they have grown (a million boxes' answer is some 110 MB, and fresh
/// memory costs the OS a page fault and a zeroing per page). `found` is
/// replaced only once every check has passed.
void find_contacts(box_view boxes, const collide_options& options, float margin, scene_contacts& found);

/// find_contacts on double rows (see "Double rows" above): every pair of
/// find_pairs(boxes, options) and, with margin > 0, every other pair within
/// the margin, each with its double contact, bit for bit
/// contact_pairs(store, pairs, {options.use, options.threads, margin}) over
/// the same rows. Throws invalid_input for float rows, an invalid box (as
/// find_pairs: the row and field named), a method that does not run on
/// doubles of the boxes' kind, a margin that is negative or not finite, a
/// pose whose c·c + s·s is not a normal double and, on corners, a quad that
/// is not strictly convex in double (as contact_pairs over double stores);
/// unsupported_backend for a backend this CPU lacks.
scene_contacts64 find_contacts64(box_view boxes, const collide_options& options, double margin = 0.0);

/// find_contacts64 into `found`, whose vectors keep their memory from one
/// call to the next; `found` is replaced only once every check has passed.
void find_contacts(box_view boxes, const collide_options& options, double margin, scene_contacts64& found);

}  // namespace obbsat
