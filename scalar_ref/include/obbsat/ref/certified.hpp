// The certified separating-edge test: a float fast path that either proves
// how two quads relate, exactly, or says it cannot. Method `exact` settles the
// undecided pairs with the exact oracle (obbsat/oracle/contact.hpp).
//
// Ground truth: two closed convex quads are disjoint iff some edge line of one
// has all four corners of the other strictly on its outer side. So, with every
// orientation d = e x (r - p) (edge e from corner p, other corner r) known to
// within an error bound, a pair is proven separated when some edge has all four
// other corners certified outside, and proven intersecting when every edge has
// some other corner certified inside; both quads must first be proven strictly
// convex (all four turns certified of one sign), which also gives their winding.
//
// Contract, the exact float32 operations in order (no FMA):
//   1. Extent of each quad: xmin, xmax, ymin, ymax over its corners UL, UR, LR,
//      LL, folded with min-pick u < v ? u : v and max-pick u > v ? u : v; its
//      area = (xmax - xmin) * (ymax - ymin). Extent of the pair: the min-pick
//      and max-pick of A's and B's (A first); area likewise.
//   2. Guard: decide nothing unless 2^-80 <= area <= 2^100 for the pair and
//      2^-80 <= area for each quad (no product below the normal range matters,
//      none overflows).
//   3. bound = area * 2^-20 for the pair; own_bound = area * 2^-20 per quad.
//   4. Edges e_k = q_{k+1} - q_k per coordinate, k = 0..3 in corner order, q_4 = q_0.
//   5. Turns t_k = (e_k.x * e_{k+1}.y) - (e_k.y * e_{k+1}.x). A quad is convex with
//      winding s = +1 if every t_k > own_bound, s = -1 if every t_k < -own_bound.
//      (A turn involves one quad only, so its own extent bounds its error: a
//      small quad beside a large one is still proven convex.)
//   6. For each edge k of A and each corner r of B (and B's edges against A's
//      corners): d = (e_k.x * (r.y - q_k.y)) - (e_k.y * (r.x - q_k.x)), then
//      sd = d with its sign flipped when s = -1. Outside iff sd < -bound, inside
//      iff sd > bound.
//   7. separated   iff both convex and some edge has all four corners outside;
//      intersecting iff both convex and every edge has a corner inside;
//      otherwise undecided.
//
// Why the bound holds: every exact difference above is at most w (x) or h (y)
// in magnitude, where w and h are the exact widths of the extent the bound is
// taken from, so each product is at most w h (1 + u)^3 and the computed d is
// within (3 + 16u) u * 2 w h (1 + u)^3 of the exact one (u = 2^-24, Shewchuk's
// orient2d bound A); the rounding of w, h and area costs (1 + u)^-3 more. That
// is below 6.001 u * area, and bound = 16 u * area. Subnormal differences are
// exact, and a product that falls below 2^-126 errs by at most 2^-150, far
// under the bound when area >= 2^-80. The full derivation is in docs/exact.md.
#pragma once

#include <obbsat/rect.hpp>

namespace obbsat::ref {

/// What the fast path proved about a pair; at most one of the two is true.
struct certified_verdict {
    bool separated;     ///< proven: the closed quads share no point
    bool intersecting;  ///< proven: the closed quads share a point
};

/// The certified separating-edge test on (a, b), as specified above.
certified_verdict certify(const rect& a, const rect& b);

}  // namespace obbsat::ref
