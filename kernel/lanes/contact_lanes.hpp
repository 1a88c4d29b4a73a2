// Contacts in lanes, one pair per lane: obbsat/ref/contact.hpp's steps written
// once over the xsimd architecture and the real type (float for the float
// stores, double for pose_records64 and rect_records64, every operation the
// double reference's in double), without branches (every choice a select,
// every argmax a fold of strict compares, so ties go to the lowest index as in
// the reference). contact_batch.hpp drives them over a batch. Private to each
// per-ISA object (README.md).
#pragma once

#include "lanes/lanes.hpp"
#include "lanes/pose64_lanes.hpp"
#include "lanes/pose_lanes.hpp"

#include <obbsat/contact_manifold.hpp>

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace obbsat::detail {
namespace {

/// One real per lane: float or double, 4 or 2 per SSE2 vector, 8 or 4 per
/// AVX2, 16 or 8 per AVX-512. Every step below is written once over both.
template <class Arch, class Real>
using real_lanes = xsimd::batch<Real, Arch>;

template <class Arch, class Real>
using real_mask = xsimd::batch_bool<Real, Arch>;

/// xsimd::select(m, t, f): one VBLENDVPS (VBLENDVPD) on AVX2, where GCC 12
/// rewrites the blend of a mask built by and/or of compares (or carried from
/// one step to the next) as a compare of the mask's sign bits with zero
/// first: an extra instruction on a select's path, some 30 a vector of
/// contacts. A blend of a compare's mask is the same select either way.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_lanes<Arch, Real> pick(const real_mask<Arch, Real>& m, const real_lanes<Arch, Real>& t,
                                               const real_lanes<Arch, Real>& f) {
#if defined(__AVX2__) && !defined(__AVX512F__)
    if constexpr (std::is_same<Arch, xsimd::avx2>::value) {
        typename real_lanes<Arch, Real>::register_type out;
        if constexpr (std::is_same<Real, float>::value) {
            __asm__("vblendvps %3, %2, %1, %0" : "=x"(out) : "x"(f.data), "xm"(t.data), "x"(m.data));
        } else {
            __asm__("vblendvpd %3, %2, %1, %0" : "=x"(out) : "x"(f.data), "xm"(t.data), "x"(m.data));
        }
        return out;
    }
#endif
    return xsimd::select(m, t, f);
}

/// -x, the sign bit flipped as the reference's negation flips it. Not
/// xsimd's unary minus: for AVX-512, xsimd 8.1 computes it as 0 - x, which
/// turns -(+0) into +0 where the reference gives -0.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_lanes<Arch, Real> negated(const real_lanes<Arch, Real>& x) {
    return xsimd::bitwise_xor(x, real_lanes<Arch, Real>(Real(-0.0)));
}

/// A box per lane: vertices relative to the origin and outward face normals.
template <class Arch, class Real>
struct contact_box_lanes {
    real_lanes<Arch, Real> vx[4], vy[4], nx[4], ny[4];
    real_lanes<Arch, Real> inv[4];  ///< step 1: the reciprocal length of each face normal
};

/// The pose box of the reference: fields cx, cy, hx, hy, c, s; origin (ox0, oy0).
template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_box_lanes<Arch, Real> contact_pose_box(const real_lanes<Arch, Real>* f,
                                                                  const real_lanes<Arch, Real>& origin_x,
                                                                  const real_lanes<Arch, Real>& origin_y,
                                                                  const real_lanes<Arch, Real>& inv) {
    using batch = real_lanes<Arch, Real>;
    const batch ox = f[0] - origin_x, oy = f[1] - origin_y;
    const batch c = f[4], s = f[5];
    const batch ux = f[2] * c, uy = f[2] * s;
    const batch wx = f[3] * s, wy = f[3] * c;
    contact_box_lanes<Arch, Real> box;
    box.vx[0] = (ox - ux) - wx;
    box.vy[0] = (oy - uy) + wy;
    box.vx[1] = (ox + ux) - wx;
    box.vy[1] = (oy + uy) + wy;
    box.vx[2] = (ox + ux) + wx;
    box.vy[2] = (oy + uy) - wy;
    box.vx[3] = (ox - ux) + wx;
    box.vy[3] = (oy - uy) - wy;
    box.nx[0] = negated<Arch, Real>(s);
    box.ny[0] = c;
    box.nx[1] = c;
    box.ny[1] = s;
    box.nx[2] = s;
    box.ny[2] = negated<Arch, Real>(c);
    box.nx[3] = negated<Arch, Real>(c);
    box.ny[3] = negated<Arch, Real>(s);
    // The four faces' dot(n, n) are (s·s) + (c·c) in some order of the same
    // two exact squares: one inv, computed by the caller.
    for (int k = 0; k < 4; ++k) {
        box.inv[k] = inv;
    }
    return box;
}

/// The corner box of the reference: fields the corners UL, UR, LR, LL (x, y each).
template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_box_lanes<Arch, Real> contact_corner_box(const real_lanes<Arch, Real>* f,
                                                                    const real_lanes<Arch, Real>& origin_x,
                                                                    const real_lanes<Arch, Real>& origin_y) {
    using batch = real_lanes<Arch, Real>;
    batch ex[4], ey[4];
    for (int k = 0; k < 4; ++k) {
        const int next = (k + 1) & 3;
        ex[k] = f[2 * next] - f[2 * k];
        ey[k] = f[2 * next + 1] - f[2 * k + 1];
    }
    const auto clockwise = ((ex[0] * ey[1]) - (ey[0] * ex[1])) < batch(Real(0));
    contact_box_lanes<Arch, Real> box;
    for (int k = 0; k < 4; ++k) {
        box.vx[k] = f[2 * k] - origin_x;
        box.vy[k] = f[2 * k + 1] - origin_y;
        box.nx[k] = pick<Arch, Real>(clockwise, negated<Arch, Real>(ey[k]), ey[k]);
        box.ny[k] = pick<Arch, Real>(clockwise, ex[k], negated<Arch, Real>(ex[k]));
        box.inv[k] = batch(Real(1)) / xsimd::sqrt((box.nx[k] * box.nx[k]) + (box.ny[k] * box.ny[k]));
    }
    return box;
}

// The integers of a contact (its point count, its feature keys) travel with
// its reals as lanes holding their bits, as the 4-byte integer at the start
// of an equally wide field (the rest of a double's eight bytes zero, as the
// reference's zeroed padding). Nothing of xsimd's integer batches is used but
// float's conversion to int32 (one instruction on every ISA): AVX2 builds
// other integer operations from SSE2 halves, templates that two per-ISA
// objects would both define (README.md). Nor are the bits made as subnormal
// products, which a caller's flush-to-zero mode would wipe out.

/// The lanes whose bits are the integers `n` (whole reals below 2^24): for
/// float the int32 conversion; for double n + 2^52, exact, which holds n in
/// its low mantissa bits below the bits of 2^52, cleared by an xor.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_lanes<Arch, Real> integer_bits(const real_lanes<Arch, Real>& n) {
    using batch = real_lanes<Arch, Real>;
    if constexpr (std::is_same<Real, float>::value) {
        return xsimd::bitwise_cast<batch>(xsimd::batch_cast<std::int32_t>(n));
    } else {
        const batch two_to_52(0x1p52);
        return xsimd::bitwise_xor(n + two_to_52, two_to_52);
    }
}

/// The lanes whose bits are contact_feature's four bytes (index_a, type_a,
/// index_b, type_b; little-endian) for the indices of A's and B's features,
/// of which exactly one is a face (type 1): B's where b_is_face, else A's,
/// as every feature of a clipped point. For float the three low bytes make
/// a whole float below 2^24 and type_b's bit, bit 24, is OR-ed in as the
/// bits of 2^-125 (exponent field 2); a double holds all four bytes as one
/// whole number. Every sum is of whole numbers below 2^25, so exact.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_lanes<Arch, Real> feature_bits(const real_lanes<Arch, Real>& index_a,
                                                       const real_lanes<Arch, Real>& index_b,
                                                       const real_mask<Arch, Real>& b_is_face) {
    using batch = real_lanes<Arch, Real>;
    const batch indices = index_a + (batch(Real(0x1p16)) * index_b);
    if constexpr (std::is_same<Real, float>::value) {
        static_assert(0x1p-125f == 1.17549435e-38f * 2.0f, "2^-125 has the bits 0x01000000");
        const batch zero(0.0f);
        return xsimd::bitwise_or(integer_bits<Arch, Real>(indices + pick<Arch, Real>(b_is_face, zero, batch(0x1p8f))),
                                 pick<Arch, Real>(b_is_face, batch(0x1p-125f), zero));
    } else {
        return integer_bits<Arch, Real>(indices + pick<Arch, Real>(b_is_face, batch(0x1p24), batch(0x1p8)));
    }
}

/// The contact of each lane's pair, as the reference's fields; the point
/// count and the feature keys hold the bits of their integers (integer_bits,
/// feature_bits).
template <class Arch, class Real>
struct contact_out_lanes {
    real_lanes<Arch, Real> nx, ny, depth, count;
    real_lanes<Arch, Real> x[2], y[2], separation[2], feature[2];
};

/// Step 2 for one box's faces against the other's vertices, and the argmax
/// fold: the separation, index, normal, its reciprocal length and the face's
/// ends of the best face.
template <class Arch, class Real>
struct best_face_lanes {
    real_lanes<Arch, Real> sep, index, nx, ny, inv, x1, y1, x2, y2;
};

template <class Arch, class Real>
OBBSAT_LANE_INLINE best_face_lanes<Arch, Real> best_face_lanes_of(const contact_box_lanes<Arch, Real>& faces,
                                                                  const contact_box_lanes<Arch, Real>& other) {
    using batch = real_lanes<Arch, Real>;
    best_face_lanes<Arch, Real> best;
    for (int k = 0; k < 4; ++k) {
        // dot(n[k], other.v[j] - v[k]), each difference per coordinate.
        auto along = [&](int j) {
            return (faces.nx[k] * (other.vx[j] - faces.vx[k])) + (faces.ny[k] * (other.vy[j] - faces.vy[k]));
        };
        batch least = along(0);
        for (int j = 1; j < 4; ++j) {
            least = min_pick(along(j), least);
        }
        const batch sep = least * faces.inv[k];
        const int next = (k + 1) & 3;
        if (k == 0) {
            best = best_face_lanes<Arch, Real>{sep,         batch(Real(0)), faces.nx[0],    faces.ny[0],   faces.inv[0],
                                               faces.vx[0], faces.vy[0],    faces.vx[next], faces.vy[next]};
        } else {
            const auto better = sep > best.sep;
            best.sep = pick<Arch, Real>(better, sep, best.sep);
            best.index = pick<Arch, Real>(better, batch(static_cast<Real>(k)), best.index);
            best.nx = pick<Arch, Real>(better, faces.nx[k], best.nx);
            best.ny = pick<Arch, Real>(better, faces.ny[k], best.ny);
            best.inv = pick<Arch, Real>(better, faces.inv[k], best.inv);
            best.x1 = pick<Arch, Real>(better, faces.vx[k], best.x1);
            best.y1 = pick<Arch, Real>(better, faces.vy[k], best.y1);
            best.x2 = pick<Arch, Real>(better, faces.vx[next], best.x2);
            best.y2 = pick<Arch, Real>(better, faces.vy[next], best.y2);
        }
    }
    return best;
}

/// Step 3's span of a box.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_lanes<Arch, Real> span_lanes(const contact_box_lanes<Arch, Real>& box) {
    real_lanes<Arch, Real> lo_x = box.vx[0], hi_x = box.vx[0], lo_y = box.vy[0], hi_y = box.vy[0];
    for (int j = 1; j < 4; ++j) {
        lo_x = min_pick(box.vx[j], lo_x);
        hi_x = max_pick(box.vx[j], hi_x);
        lo_y = min_pick(box.vy[j], lo_y);
        hi_y = max_pick(box.vy[j], hi_y);
    }
    return max_pick(hi_x - lo_x, hi_y - lo_y);
}

/// Box b, or box a where `pick_a`.
template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_box_lanes<Arch, Real> either_box(const real_mask<Arch, Real>& pick_a,
                                                            const contact_box_lanes<Arch, Real>& a,
                                                            const contact_box_lanes<Arch, Real>& b) {
    contact_box_lanes<Arch, Real> out;
    for (int k = 0; k < 4; ++k) {
        out.vx[k] = pick<Arch, Real>(pick_a, a.vx[k], b.vx[k]);
        out.vy[k] = pick<Arch, Real>(pick_a, a.vy[k], b.vy[k]);
        out.nx[k] = pick<Arch, Real>(pick_a, a.nx[k], b.nx[k]);
        out.ny[k] = pick<Arch, Real>(pick_a, a.ny[k], b.ny[k]);
        out.inv[k] = pick<Arch, Real>(pick_a, a.inv[k], b.inv[k]);
    }
    return out;
}

/// What steps 1 to 3 choose, per lane: the reference box (B where flip), its
/// face r with its normal, that normal's reciprocal length and the face's
/// ends, and the reference box's best separation (sep).
template <class Arch, class Real>
struct reference_lanes {
    real_mask<Arch, Real> flip;
    real_lanes<Arch, Real> r, sep, nx, ny, inv, q1x, q1y, q2x, q2y;
};

/// Marks lanes whose pairs are all within the margin (both best separations
/// at most it), as every pair the second pass of contact_pose_batch reads:
/// step 6's test of the margin is then true in every lane, and left out.
struct known_within {};

/// `m` where both best separations are at most the margin (`within`).
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_mask<Arch, Real> and_within(const real_mask<Arch, Real>& within,
                                                    const real_mask<Arch, Real>& m) {
    return within & m;
}

template <class Arch, class Real>
OBBSAT_LANE_INLINE real_mask<Arch, Real> and_within(known_within, const real_mask<Arch, Real>& m) {
    return m;
}

/// Steps 1 to 3 of the reference for boxes a and b (the corner rule); sets
/// `within` where both best separations are at most the margin.
template <class Arch, class Real>
OBBSAT_LANE_INLINE reference_lanes<Arch, Real> reference_of_boxes(const contact_box_lanes<Arch, Real>& a,
                                                                  const contact_box_lanes<Arch, Real>& b,
                                                                  Real margin, real_mask<Arch, Real>& within) {
    // Step 2 (step 1 is the boxes' inv).
    const best_face_lanes<Arch, Real> fa = best_face_lanes_of<Arch, Real>(a, b);
    const best_face_lanes<Arch, Real> fb = best_face_lanes_of<Arch, Real>(b, a);
    // Step 3.
    const real_lanes<Arch, Real> tol =
        real_lanes<Arch, Real>(Real(0x1p-10)) * min_pick(span_lanes<Arch, Real>(a), span_lanes<Arch, Real>(b));
    const auto flip = fb.sep > (fa.sep + tol);
    const real_lanes<Arch, Real> limit(margin);
    within = (fa.sep <= limit) & (fb.sep <= limit);
    return reference_lanes<Arch, Real>{flip,
                                       pick<Arch, Real>(flip, fb.index, fa.index),
                                       pick<Arch, Real>(flip, fb.sep, fa.sep),
                                       pick<Arch, Real>(flip, fb.nx, fa.nx),
                                       pick<Arch, Real>(flip, fb.ny, fa.ny),
                                       pick<Arch, Real>(flip, fb.inv, fa.inv),
                                       pick<Arch, Real>(flip, fb.x1, fa.x1),
                                       pick<Arch, Real>(flip, fb.y1, fa.y1),
                                       pick<Arch, Real>(flip, fb.x2, fa.x2),
                                       pick<Arch, Real>(flip, fb.y2, fa.y2)};
}

/// Step 4's normal and depth, with no point (count 0, every point field
/// zero), from the reference box's best separation (sep): the contact of a
/// pair whose best faces separate it by more than the margin, and what steps
/// 5 to 8 start from.
template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_out_lanes<Arch, Real> contact_without_points(const real_mask<Arch, Real>& flip,
                                                                        const real_lanes<Arch, Real>& ux,
                                                                        const real_lanes<Arch, Real>& uy,
                                                                        const real_lanes<Arch, Real>& sep) {
    const real_lanes<Arch, Real> zero(Real(0));
    contact_out_lanes<Arch, Real> out;
    out.nx = pick<Arch, Real>(flip, negated<Arch, Real>(ux), ux);
    out.ny = pick<Arch, Real>(flip, negated<Arch, Real>(uy), uy);
    out.depth = zero - sep;
    out.count = zero;
    for (int e = 0; e < 2; ++e) {
        out.x[e] = zero;
        out.y[e] = zero;
        out.separation[e] = zero;
        out.feature[e] = zero;
    }
    return out;
}

/// Step 5's choice, per lane: the incident face k and its edge's ends p1, p2.
template <class Arch, class Real>
struct incident_edge_lanes {
    real_lanes<Arch, Real> k, p1x, p1y, p2x, p2y;
};

/// Step 5 on a box of four faces: the face most against (ux, uy).
template <class Arch, class Real>
OBBSAT_LANE_INLINE incident_edge_lanes<Arch, Real> incident_edge_of_box(const contact_box_lanes<Arch, Real>& inc,
                                                                        const real_lanes<Arch, Real>& ux,
                                                                        const real_lanes<Arch, Real>& uy) {
    using batch = real_lanes<Arch, Real>;
    incident_edge_lanes<Arch, Real> edge;
    batch most_against;
    for (int f = 0; f < 4; ++f) {
        const int next = (f + 1) & 3;
        const batch along = ((inc.nx[f] * ux) + (inc.ny[f] * uy)) * inc.inv[f];
        const batch x1 = inc.vx[f], y1 = inc.vy[f], x2 = inc.vx[next], y2 = inc.vy[next];
        if (f == 0) {
            most_against = along;
            edge = incident_edge_lanes<Arch, Real>{batch(Real(0)), x1, y1, x2, y2};
        } else {
            const auto better = along < most_against;
            most_against = pick<Arch, Real>(better, along, most_against);
            edge.k = pick<Arch, Real>(better, batch(static_cast<Real>(f)), edge.k);
            edge.p1x = pick<Arch, Real>(better, x1, edge.p1x);
            edge.p1y = pick<Arch, Real>(better, y1, edge.p1y);
            edge.p2x = pick<Arch, Real>(better, x2, edge.p2x);
            edge.p2y = pick<Arch, Real>(better, y2, edge.p2y);
        }
    }
    return edge;
}

/// Steps 6 to 8 of the reference, and step 4's outputs, from the reference
/// face (ref), its unit normal (ux, uy), the incident edge and where both
/// best separations are at most the margin (within: a mask, or known_within).
template <class Arch, class Real, class Within>
OBBSAT_LANE_INLINE contact_out_lanes<Arch, Real> clipped_manifold_lanes(
    const reference_lanes<Arch, Real>& ref, const Within& within, const real_lanes<Arch, Real>& ux,
    const real_lanes<Arch, Real>& uy, const incident_edge_lanes<Arch, Real>& edge, const real_lanes<Arch, Real>& origin_x,
    const real_lanes<Arch, Real>& origin_y, Real margin_value) {
    using batch = real_lanes<Arch, Real>;
    const batch zero(Real(0)), one(Real(1)), four(Real(4)), margin(margin_value);
    const auto flip = ref.flip;
    const batch r = ref.r, q1x = ref.q1x, q1y = ref.q1y, q2x = ref.q2x, q2y = ref.q2y;
    const batch k = edge.k, p1x = edge.p1x, p1y = edge.p1y, p2x = edge.p2x, p2y = edge.p2y;

    contact_out_lanes<Arch, Real> out = contact_without_points<Arch, Real>(flip, ux, uy, ref.sep);

    // Step 6: clip to the side planes.
    const batch tx = q2x - q1x, ty = q2y - q1y;
    const batch T = (tx * tx) + (ty * ty);
    const batch tau[2] = {((p1x - q1x) * tx) + ((p1y - q1y) * ty), ((p2x - q1x) * tx) + ((p2y - q1y) * ty)};
    // Written without negating a mask: xsimd 8.1's AVX2 negation compares
    // masks through SSE2 halves, code that two per-ISA objects would share.
    const auto reaches_low_side = (tau[0] >= zero) | (tau[1] >= zero);
    const auto reaches_high_side = (tau[0] <= T) | (tau[1] <= T);
    const auto in_reach = and_within<Arch, Real>(within, reaches_low_side & reaches_high_side);
    const batch g = one / (tau[0] - tau[1]);
    const batch lambda_low = tau[0] * g, lambda_high = (tau[0] - T) * g;
    const batch along_x = p2x - p1x, along_y = p2y - p1y;
    const batch r_next = pick<Arch, Real>((r + one) == four, zero, r + one);
    const batch k_next = pick<Arch, Real>((k + one) == four, zero, k + one);
    const batch ex[2] = {p1x, p2x}, ey[2] = {p1y, p2y};
    const batch vertex_of_incident[2] = {k, k_next};

    batch px[2], py[2], sep[2], feature[2];
    real_mask<Arch, Real> keep[2];
    for (int e = 0; e < 2; ++e) {
        const auto below = tau[e] < zero, above = tau[e] > T;
        const auto moved = below | above;
        const batch lambda = pick<Arch, Real>(below, lambda_low, lambda_high);
        px[e] = pick<Arch, Real>(moved, p1x + (lambda * along_x), ex[e]);
        py[e] = pick<Arch, Real>(moved, p1y + (lambda * along_y), ey[e]);
        // Step 8: an end left in place is the incident vertex on reference
        // face r; a moved one is reference vertex r (below) or r + 1 (above:
        // T is a sum of squares, so never both) on incident face k.
        const batch ref_index = pick<Arch, Real>(above, r_next, r);
        const batch inc_index = pick<Arch, Real>(moved, k, vertex_of_incident[e]);
        feature[e] = feature_bits<Arch, Real>(pick<Arch, Real>(flip, inc_index, ref_index),
                                              pick<Arch, Real>(flip, ref_index, inc_index), moved ^ flip);
        sep[e] = ((px[e] - q1x) * ux) + ((py[e] - q1y) * uy);
    }
    // Step 7: within the margin, or the nearer point of a touching or
    // overlapping pair; a kept separation above the margin reads as it.
    const auto touching = ref.sep <= zero;
    for (int e = 0; e < 2; ++e) {
        keep[e] = in_reach & ((sep[e] <= margin) | (touching & (sep[e] <= sep[1 - e])));
    }
    for (int e = 0; e < 2; ++e) {
        sep[e] = pick<Arch, Real>(sep[e] <= margin, sep[e], margin);
    }
    // The second point only when it is not the first again.
    const auto repeats = keep[0] & (px[1] == px[0]) & (py[1] == py[0]);
    keep[1] = keep[1] & (pick<Arch, Real>(repeats, one, zero) == zero);
    // Kept points first, unused slots zero.
    const auto second_kept = keep[0] & keep[1];
    for (int e = 0; e < 2; ++e) {
        px[e] = origin_x + px[e];
        py[e] = origin_y + py[e];
    }
    out.x[0] = pick<Arch, Real>(keep[0], px[0], pick<Arch, Real>(keep[1], px[1], zero));
    out.y[0] = pick<Arch, Real>(keep[0], py[0], pick<Arch, Real>(keep[1], py[1], zero));
    out.separation[0] = pick<Arch, Real>(keep[0], sep[0], pick<Arch, Real>(keep[1], sep[1], zero));
    out.feature[0] = pick<Arch, Real>(keep[0], feature[0], pick<Arch, Real>(keep[1], feature[1], zero));
    out.x[1] = pick<Arch, Real>(second_kept, px[1], zero);
    out.y[1] = pick<Arch, Real>(second_kept, py[1], zero);
    out.separation[1] = pick<Arch, Real>(second_kept, sep[1], zero);
    out.feature[1] = pick<Arch, Real>(second_kept, feature[1], zero);
    out.count = integer_bits<Arch, Real>(pick<Arch, Real>(keep[0], one, zero) + pick<Arch, Real>(keep[1], one, zero));
    return out;
}

/// Steps 4 to 8 of the reference from the choice of the reference face and
/// the incident box (B, or A where flip).
template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_out_lanes<Arch, Real> manifold_lanes_of(const contact_box_lanes<Arch, Real>& inc,
                                                                   const reference_lanes<Arch, Real>& ref,
                                                                   const real_mask<Arch, Real>& within,
                                                                   const real_lanes<Arch, Real>& origin_x,
                                                                   const real_lanes<Arch, Real>& origin_y,
                                                                   Real margin) {
    const real_lanes<Arch, Real> ux = ref.nx * ref.inv, uy = ref.ny * ref.inv;
    return clipped_manifold_lanes<Arch, Real>(ref, within, ux, uy, incident_edge_of_box<Arch, Real>(inc, ux, uy),
                                              origin_x, origin_y, margin);
}

/// Face j's edge of pose boxes, per lane, without building the boxes: pose
/// fields cx, cy, hx, hy, c, s (f) relative to the origin, j a whole float 0
/// to 3. The reference's vertex k is ((ox ± ux) ± wx, (oy ± uy) ± wy) with
/// signs that depend on k alone; x − y is x + (−y) exactly, so each is written
/// as sums of the terms with their sign bits set: `a` on u for k = 0 and 3,
/// `b` on w for k = 0 and 1 (on wy the other way round). Face j's second end,
/// vertex j + 1, takes u's sign from the complement of b and w's from a.
template <class Arch, class Real>
OBBSAT_LANE_INLINE incident_edge_lanes<Arch, Real> pose_edge_lanes(const real_lanes<Arch, Real>* f,
                                                                   const real_lanes<Arch, Real>& origin_x,
                                                                   const real_lanes<Arch, Real>& origin_y,
                                                                   const real_lanes<Arch, Real>& j) {
    using batch = real_lanes<Arch, Real>;
    const batch sign(Real(-0.0)), none(Real(0));
    const batch ox = f[0] - origin_x, oy = f[1] - origin_y;
    const batch c = f[4], s = f[5];
    const batch ux = f[2] * c, uy = f[2] * s;
    const batch wx = f[3] * s, wy = f[3] * c;
    const batch a = pick<Arch, Real>((j == batch(Real(0))) | (j == batch(Real(3))), sign, none);
    const batch b = pick<Arch, Real>(j < batch(Real(2)), sign, none);
    const batch not_a = xsimd::bitwise_xor(a, sign), not_b = xsimd::bitwise_xor(b, sign);
    auto signed_by = [](const batch& x, const batch& bit) { return xsimd::bitwise_xor(x, bit); };
    incident_edge_lanes<Arch, Real> edge;
    edge.k = j;
    edge.p1x = (ox + signed_by(ux, a)) + signed_by(wx, b);
    edge.p1y = (oy + signed_by(uy, a)) + signed_by(wy, not_b);
    edge.p2x = (ox + signed_by(ux, not_b)) + signed_by(wx, a);
    edge.p2y = (oy + signed_by(uy, not_b)) + signed_by(wy, not_a);
    return edge;
}

/// Method local's offsets and reaches (steps 1 to 4) for pose fields cx, cy,
/// hx, hy, c, s of A and of B: the float pose lanes' steps on float, the
/// double ones' on double (the references local and local64).
template <class Arch, class Real>
OBBSAT_LANE_INLINE auto local_axes_lanes(const real_lanes<Arch, Real>* fa, const real_lanes<Arch, Real>* fb) {
    if constexpr (std::is_same<Real, float>::value) {
        const pose_lanes<Arch> pa{fa[0], fa[1], fa[2], fa[3], fa[4], fa[5]};
        const pose_lanes<Arch> pb{fb[0], fb[1], fb[2], fb[3], fb[4], fb[5]};
        typename pose_steps<Arch>::axes axes;
        real_lanes<Arch, Real> P, Q;
        pose_steps<Arch>::first_axes(pa, pb, axes, P, Q);
        pose_steps<Arch>::second_axes(pa, pb, axes, P, Q);
        return axes;
    } else {
        return pose64_steps<Arch>::axes_of(pose64_lanes<Arch>{fa[0], fa[1], fa[2], fa[3], fa[4], fa[5]},
                                           pose64_lanes<Arch>{fb[0], fb[1], fb[2], fb[3], fb[4], fb[5]});
    }
}

/// What the pose steps P1 to P3 and step 4 choose, per lane: the reference
/// pose (B where flip), its face r, the best separations of A's and of B's
/// faces, the boxes' reciprocal lengths and the unit normal u of face r.
template <class Arch, class Real>
struct pose_reference_lanes {
    real_mask<Arch, Real> flip;
    real_lanes<Arch, Real> r, sa, sb, inv_a, inv_b, ux, uy;
};

/// Pose steps P1 to P3 and step 4's normal for fields cx, cy, hx, hy, c, s of
/// A and of B.
template <class Arch, class Real>
OBBSAT_LANE_INLINE pose_reference_lanes<Arch, Real> pose_reference_of(const real_lanes<Arch, Real>* fa,
                                                                      const real_lanes<Arch, Real>* fb) {
    using batch = real_lanes<Arch, Real>;
    const batch zero(Real(0)), one(Real(1)), two(Real(2)), three(Real(3));
    // Pose step 1.
    const batch len_a = xsimd::sqrt((fa[4] * fa[4]) + (fa[5] * fa[5]));
    const batch len_b = xsimd::sqrt((fb[4] * fb[4]) + (fb[5] * fb[5]));
    const batch inv_a = one / len_a, inv_b = one / len_b;

    // Pose step 2: method local's offsets and reaches.
    const auto axes = local_axes_lanes<Arch, Real>(fa, fb);
    batch sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (xsimd::abs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? inv_a : inv_b);
    }
    const auto a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    const batch sa = pick<Arch, Real>(a_on_y, sep[1], sep[0]), sb = pick<Arch, Real>(b_on_y, sep[3], sep[2]);

    // Pose step 3.
    const batch size_a = (fa[2] + fa[3]) * len_a, size_b = (fb[2] + fb[3]) * len_b;
    const batch tol = batch(Real(0x1p-10)) * min_pick(size_a, size_b);
    const auto flip = sb > (sa + tol);

    // The face of the chosen axis that faces the other box.
    const batch r_a = pick<Arch, Real>(a_on_y, pick<Arch, Real>(axes.offset[1] >= zero, zero, two),
                                    pick<Arch, Real>(axes.offset[0] >= zero, one, three));
    const batch r_b = pick<Arch, Real>(b_on_y, pick<Arch, Real>(axes.offset[3] >= zero, two, zero),
                                    pick<Arch, Real>(axes.offset[2] >= zero, three, one));
    const batch r = pick<Arch, Real>(flip, r_b, r_a);
    // Step 4's normal: face r's of the reference pose, n = (−s, c), (c, s),
    // (s, −c), (−c, −s) for r = 0 to 3, only signs and places changing.
    const batch sign(Real(-0.0));
    const batch ref_c = pick<Arch, Real>(flip, fb[4], fa[4]), ref_s = pick<Arch, Real>(flip, fb[5], fa[5]);
    const auto odd = (r == one) | (r == three);
    const batch nx = xsimd::bitwise_xor(pick<Arch, Real>(odd, ref_c, ref_s),
                                        pick<Arch, Real>((r == zero) | (r == three), sign, zero));
    const batch ny = xsimd::bitwise_xor(pick<Arch, Real>(odd, ref_s, ref_c), pick<Arch, Real>(r >= two, sign, zero));
    const batch inv = pick<Arch, Real>(flip, inv_b, inv_a);
    return pose_reference_lanes<Arch, Real>{flip, r, sa, sb, inv_a, inv_b, nx * inv, ny * inv};
}

/// Whether a lane's best faces leave its pair within the margin: only those
/// lanes can have points (step 7), the others are contact_without_points.
template <class Arch, class Real>
OBBSAT_LANE_INLINE real_mask<Arch, Real> may_have_points(const pose_reference_lanes<Arch, Real>& p, Real margin) {
    const real_lanes<Arch, Real> limit(margin);
    return (p.sa <= limit) & (p.sb <= limit);
}

/// What steps 5 to 8 read of pose_reference_of's choice, per lane: the
/// reference pose (B where flip), its face r and best separation, the
/// incident pose's reciprocal length and the unit normal u of face r.
template <class Arch, class Real>
struct pose_choice_lanes {
    real_mask<Arch, Real> flip;
    real_lanes<Arch, Real> r, sep, inc_inv, ux, uy;
};

template <class Arch, class Real>
OBBSAT_LANE_INLINE pose_choice_lanes<Arch, Real> pose_choice_of(const pose_reference_lanes<Arch, Real>& p) {
    return pose_choice_lanes<Arch, Real>{p.flip, p.r, pick<Arch, Real>(p.flip, p.sb, p.sa),
                                         pick<Arch, Real>(p.flip, p.inv_a, p.inv_b), p.ux, p.uy};
}

/// The contact of poses, per lane: fields cx, cy, hx, hy, c, s of A and of B
/// and what pose_reference_of chose for them (the reference's pose steps,
/// `within` where both best separations are at most the margin: a mask, or
/// known_within), then steps 4 to 8.
template <class Arch, class Real, class Within>
OBBSAT_LANE_INLINE contact_out_lanes<Arch, Real> contact_pose_lanes_from(const real_lanes<Arch, Real>* fa,
                                                                         const real_lanes<Arch, Real>* fb,
                                                                         const pose_choice_lanes<Arch, Real>& p,
                                                                         const Within& within, Real margin) {
    using batch = real_lanes<Arch, Real>;
    const batch zero(Real(0));
    const batch origin_x = fa[0], origin_y = fa[1];
    const auto flip = p.flip;
    const batch r = p.r, ux = p.ux, uy = p.uy, inc_inv = p.inc_inv;

    // Step 5 on the incident pose: its faces' normals are ±(−s, c) and ±(c,
    // s), so faces 2 and 3 are along faces 0 and 1 negated (exactly: only
    // signs change, and a zero's sign does not change a strict compare).
    batch inc_fields[6], ref_fields[6];
    for (int f = 0; f < 6; ++f) {
        ref_fields[f] = pick<Arch, Real>(flip, fb[f], fa[f]);
        inc_fields[f] = pick<Arch, Real>(flip, fa[f], fb[f]);
    }
    const batch inc_c = inc_fields[4], inc_s = inc_fields[5];
    const batch along_0 = ((negated<Arch, Real>(inc_s) * ux) + (inc_c * uy)) * inc_inv;
    const batch along_1 = ((inc_c * ux) + (inc_s * uy)) * inc_inv;
    const batch along[4] = {along_0, along_1, negated<Arch, Real>(along_0), negated<Arch, Real>(along_1)};
    batch k = zero, most_against = along[0];
    for (int f = 1; f < 4; ++f) {
        const auto better = along[f] < most_against;
        most_against = pick<Arch, Real>(better, along[f], most_against);
        k = pick<Arch, Real>(better, batch(static_cast<Real>(f)), k);
    }
    const incident_edge_lanes<Arch, Real> edge = pose_edge_lanes<Arch, Real>(inc_fields, origin_x, origin_y, k);
    const incident_edge_lanes<Arch, Real> face = pose_edge_lanes<Arch, Real>(ref_fields, origin_x, origin_y, r);
    // The normal and its reciprocal length: what steps 6 to 8 do not read again.
    const reference_lanes<Arch, Real> ref{flip,     r,        p.sep,    ux,      uy, batch(Real(1)),
                                          face.p1x, face.p1y, face.p2x, face.p2y};
    return clipped_manifold_lanes<Arch, Real>(ref, within, ux, uy, edge, origin_x, origin_y, margin);
}

/// The contact of poses, per lane: fields cx, cy, hx, hy, c, s of A and of B
/// (the reference's pose steps, then steps 4 to 8).
template <class Arch, class Real>
OBBSAT_LANE_INLINE contact_out_lanes<Arch, Real> contact_pose_lanes_of(const real_lanes<Arch, Real>* fa,
                                                                       const real_lanes<Arch, Real>* fb, Real margin) {
    const pose_reference_lanes<Arch, Real> p = pose_reference_of<Arch, Real>(fa, fb);
    return contact_pose_lanes_from<Arch, Real>(fa, fb, pose_choice_of<Arch, Real>(p),
                                               may_have_points<Arch, Real>(p, margin), margin);
}

}  // namespace
}  // namespace obbsat::detail
