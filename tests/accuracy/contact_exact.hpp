// The contact of two boxes (obbsat/ref/contact.hpp) computed without rounding:
// the same steps as the float32 and double references (the same reference-face
// rule with its tolerance, the same incident edge, the same clipping, the same
// tie breaks), on the exact rationals the float or double inputs stand for
// (every float and every double is one, so one set of steps serves both). Every
// separation, overlap, clipped point and comparison is an exact GMP rational
// (mpq_class); the one square root per face normal is taken only where a
// value must be given out (the unit normal, the depth, the separations), as
// an mpf_class of contact_exact_bits bits. A comparison of two separations of
// faces of different lengths, x1/√N1 against x2/√N2, is decided exactly from
// the signs and x1²·N2 against x2²·N1; only the tolerance test of step 3
// (sB > sA + tol, a sum of two such roots) is decided in mpf, where a tie
// is a coincidence of irrationals that no family here builds.
//
// This is test code: it checks the float and double references, it is not a part of the
// library.
#pragma once

#include <obbsat/contact_manifold.hpp>
#include <obbsat/rect.hpp>
#include <obbsat/rect64.hpp>
#include <obbsat/rect_pose.hpp>
#include <obbsat/rect_pose64.hpp>

#include <gmpxx.h>

namespace obbsat::accuracy {

/// Bits of every mpf value here: far beyond the 100 the comparisons need.
inline constexpr unsigned contact_exact_bits = 256;

struct exact_point {
    mpq_class x;
    mpq_class y;
};

/// A box as the contact steps see it, in absolute coordinates (no origin:
/// exact subtraction loses nothing), with n2[k] = dot(n[k], n[k]).
struct exact_box {
    exact_point v[4];
    exact_point n[4];
    mpq_class n2[4];
};

/// The reference face: B's face r when flip, else A's face r.
struct face_choice {
    bool flip;
    int r;
    friend bool operator==(const face_choice& p, const face_choice& q) { return p.flip == q.flip && p.r == q.r; }
    friend bool operator!=(const face_choice& p, const face_choice& q) { return !(p == q); }
};

/// A separation x / √n2 kept as its two rationals (n2 > 0).
struct scaled_value {
    mpq_class x;
    mpq_class n2;
};

/// What steps 1 to 3 (or P1 to P3) decide, with the separations they compare.
struct exact_choice {
    face_choice face;
    scaled_value sa;  ///< the best separation of A's faces
    scaled_value sb;  ///< the best separation of B's faces
};

struct exact_contact_point {
    exact_point p;             ///< the point, exact
    mpf_class separation;      ///< its separation from the reference face
    contact_feature feature;   ///< as the reference gives it (A's, then B's)
};

struct exact_contact {
    face_choice face;
    int incident = 0;  ///< the incident face, step 5's choice
    mpf_class nx, ny;  ///< the unit normal from A to B
    mpf_class depth;
    int point_count = 0;
    exact_contact_point points[2];
    /// What decides the count near a boundary: the separations of both ends
    /// of the clipped incident edge (ends = 2 when the edge reaches the
    /// face, else 0) and the least distance of the unclipped ends from the
    /// face's side planes (0 when the face is a point).
    int ends = 0;
    mpf_class end_separation[2];
    mpf_class side_distance;
};

/// The box of pose `p` (the reference's pose rule, without rounding).
exact_box exact_box_of(const rect_pose& p);
exact_box exact_box_of(const rect_pose64& p);

/// The box of corner quad `r`, with outward normals from its exact edges;
/// false when its four exact turns are not all of one sign (a quad the float
/// test accepts may not be strictly convex in exact arithmetic).
bool exact_box_of(const rect& r, exact_box& out);
bool exact_box_of(const rect64& r, exact_box& out);

/// Steps P1 to P3 on poses, exact.
exact_choice exact_choice_of(const rect_pose& a, const rect_pose& b);
exact_choice exact_choice_of(const rect_pose64& a, const rect_pose64& b);

/// Steps 1 to 3 on boxes of corner quads, exact.
exact_choice exact_choice_of(const exact_box& a, const exact_box& b);

/// Steps 4 to 8 for a given reference face `face` (the one `choice` decided,
/// or another one, e.g. the float reference's), keeping points within
/// `margin`; the readiness tests of step 7 use `choice`'s separations. The
/// incident face is step 5's, or `incident` when it is 0 to 3 (to follow
/// the float reference through an exact tie of two incident faces).
exact_contact exact_contact_of(const exact_box& a, const exact_box& b, const exact_choice& choice,
                               const face_choice& face, double margin = 0.0, int incident = -1);

/// x / √n2 in mpf.
mpf_class value_of(const scaled_value& s);

}  // namespace obbsat::accuracy
