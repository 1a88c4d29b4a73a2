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

/// Every pair (i, j), i < j, of `boxes` that collides under options.test or,
/// with margin > 0, is within the margin (see above), and its contact on
/// options.use with options.threads. Throws invalid_input for an invalid box
/// (as find_pairs), a margin that is negative or not finite, and, on
/// corners, a quad that is not strictly convex (as contact_pairs);
/// unsupported_backend for a backend this CPU lacks. Pair filters carried by
/// `boxes` apply to both kinds of pair.
scene_contacts find_contacts(box_view boxes, const collide_options& options, float margin = 0.0f);

/// The same into `found`, whose vectors keep their memory from one call to
/// the next: a caller that finds contacts every step writes no fresh memory
/// once they have grown (a million boxes' answer is some 110 MB, and fresh
/// memory costs the OS a page fault and a zeroing per page). `found` is
/// replaced only once every check has passed.
void find_contacts(box_view boxes, const collide_options& options, float margin, scene_contacts& found);

}  // namespace obbsat
