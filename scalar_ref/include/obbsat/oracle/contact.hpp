// The exact oracle: how two rects, taken exactly as their float corners give
// them (see quad_region.hpp for the point set of a quad), relate as closed sets.
//
//   separated    they share no point;
//   touching     they share a point but no interior point (a point or a
//                segment has no interior, so any contact with one is touching);
//   overlapping  some point is interior to both.
//
// No tolerance anywhere: every decision is an exact orientation sign
// (orientation.hpp) or an exact comparison of input floats.
//
// Why the tests below are complete, for closed convex pieces P and Q (each
// region is a union of such pieces whose interiors are disjoint):
//   - P and Q are disjoint iff 0 lies outside the convex polygon P - Q, whose
//     edges are parallel to edges of P or Q; so iff some edge line of P (or of
//     Q) has all of Q (of P) strictly on its outer side; for a segment piece its
//     own line counts too, and two collinear segments are compared along it.
//   - For P and Q with positive area, their interiors are disjoint iff 0 is not
//     interior to P - Q, i.e. iff some edge line of P (or Q) has all of Q (P) on
//     its closed outer side.
//   - Two regions' interiors meet iff two of their pieces' interiors do: an open
//     set left after removing the splitting diagonals is still nonempty.
#pragma once

#include <obbsat/oracle/quad_region.hpp>
#include <obbsat/rect.hpp>

#include <cstdint>

namespace obbsat::oracle {

/// How two closed sets relate; ordered by how much they share.
enum class contact : std::uint8_t { separated, touching, overlapping };

/// 'S', 'T' or 'O', the letters of the labelled case files.
char contact_letter(contact c);

/// How the regions of `a` and `b` relate; symmetric. Throws std::invalid_argument
/// if a coordinate is not finite.
contact classify(const rect& a, const rect& b);

/// How two regions relate (for callers that keep regions of reused rects).
contact classify(const quad_region& a, const quad_region& b);

/// How two closed convex pieces relate.
contact classify(const convex_piece& a, const convex_piece& b);

/// True iff the closed regions of `a` and `b` share a point (touching counts).
bool intersects(const rect& a, const rect& b);

}  // namespace obbsat::oracle
