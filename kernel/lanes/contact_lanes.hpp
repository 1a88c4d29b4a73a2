// Contacts in lanes, one pair per lane: obbsat/ref/contact.hpp's steps written
// once over the xsimd architecture, without branches (every choice a select,
// every argmax a fold of strict compares, so ties go to the lowest index as in
// the reference). contact_batch.hpp drives them over a batch. Private to each
// per-ISA object (README.md).
#pragma once

#include "lanes/lanes.hpp"
#include "lanes/pose_lanes.hpp"

#include <obbsat/contact_manifold.hpp>

#include <cstddef>
#include <cstdint>

namespace obbsat::detail {
namespace {

/// -x, the sign bit flipped as the reference's negation flips it. Not
/// xsimd's unary minus: for AVX-512, xsimd 8.1 computes it as 0 - x, which
/// turns -(+0) into +0 where the reference gives -0.
template <class Arch>
OBBSAT_LANE_INLINE lanes<Arch> negated(const lanes<Arch>& x) {
    return xsimd::bitwise_xor(x, lanes<Arch>(-0.0f));
}

/// A box per lane: vertices relative to the origin and outward face normals.
template <class Arch>
struct contact_box_lanes {
    lanes<Arch> vx[4], vy[4], nx[4], ny[4];
    lanes<Arch> inv[4];  ///< step 1: the reciprocal length of each face normal
};

/// The pose box of the reference: fields cx, cy, hx, hy, c, s; origin (ox0, oy0).
template <class Arch>
OBBSAT_LANE_INLINE contact_box_lanes<Arch> contact_pose_box(const lanes<Arch>* f, const lanes<Arch>& origin_x,
                                                              const lanes<Arch>& origin_y, const lanes<Arch>& inv) {
    using batch = lanes<Arch>;
    const batch ox = f[0] - origin_x, oy = f[1] - origin_y;
    const batch c = f[4], s = f[5];
    const batch ux = f[2] * c, uy = f[2] * s;
    const batch wx = f[3] * s, wy = f[3] * c;
    contact_box_lanes<Arch> box;
    box.vx[0] = (ox - ux) - wx;
    box.vy[0] = (oy - uy) + wy;
    box.vx[1] = (ox + ux) - wx;
    box.vy[1] = (oy + uy) + wy;
    box.vx[2] = (ox + ux) + wx;
    box.vy[2] = (oy + uy) - wy;
    box.vx[3] = (ox - ux) + wx;
    box.vy[3] = (oy - uy) - wy;
    box.nx[0] = negated<Arch>(s);
    box.ny[0] = c;
    box.nx[1] = c;
    box.ny[1] = s;
    box.nx[2] = s;
    box.ny[2] = negated<Arch>(c);
    box.nx[3] = negated<Arch>(c);
    box.ny[3] = negated<Arch>(s);
    // The four faces' dot(n, n) are (s·s) + (c·c) in some order of the same
    // two exact squares: one inv, computed by the caller.
    for (int k = 0; k < 4; ++k) {
        box.inv[k] = inv;
    }
    return box;
}

/// The corner box of the reference: fields the corners UL, UR, LR, LL (x, y each).
template <class Arch>
OBBSAT_LANE_INLINE contact_box_lanes<Arch> contact_corner_box(const lanes<Arch>* f, const lanes<Arch>& origin_x,
                                                                const lanes<Arch>& origin_y) {
    using batch = lanes<Arch>;
    batch ex[4], ey[4];
    for (int k = 0; k < 4; ++k) {
        const int next = (k + 1) & 3;
        ex[k] = f[2 * next] - f[2 * k];
        ey[k] = f[2 * next + 1] - f[2 * k + 1];
    }
    const auto clockwise = ((ex[0] * ey[1]) - (ey[0] * ex[1])) < batch(0.0f);
    contact_box_lanes<Arch> box;
    for (int k = 0; k < 4; ++k) {
        box.vx[k] = f[2 * k] - origin_x;
        box.vy[k] = f[2 * k + 1] - origin_y;
        box.nx[k] = xsimd::select(clockwise, negated<Arch>(ey[k]), ey[k]);
        box.ny[k] = xsimd::select(clockwise, ex[k], negated<Arch>(ex[k]));
        box.inv[k] = batch(1.0f) / xsimd::sqrt((box.nx[k] * box.nx[k]) + (box.ny[k] * box.ny[k]));
    }
    return box;
}

// The integers of a contact (its point count, its feature keys) travel with
// its floats as float lanes holding their bits: a whole float converted to
// int32 (one conversion instruction on every ISA) and its bits reinterpreted.
// Nothing else of xsimd's integer batches is used: AVX2 builds some of their
// operations from SSE2 halves, templates that two per-ISA objects would both
// define (README.md). Nor are the bits made as subnormal products, which a
// caller's flush-to-zero mode would wipe out.

/// The float lanes whose bits are the int32 of the whole floats `n` (< 2^24).
template <class Arch>
OBBSAT_LANE_INLINE lanes<Arch> integer_bits(const lanes<Arch>& n) {
    return xsimd::bitwise_cast<lanes<Arch>>(xsimd::batch_cast<std::int32_t>(n));
}

/// The float lanes whose bits are contact_feature's four bytes (index_a,
/// type_a, index_b, type_b; little-endian) for codes index + 4·type of A and
/// of B. The three low bytes make a whole float below 2^24; type_b's bit,
/// bit 24, is OR-ed in as the bits of 2^-125 (exponent field 2).
template <class Arch>
OBBSAT_LANE_INLINE lanes<Arch> feature_bits(const lanes<Arch>& code_a, const lanes<Arch>& code_b) {
    using batch = lanes<Arch>;
    const batch zero(0.0f), one(1.0f), four(4.0f);
    const batch type_a = xsimd::select(code_a >= four, one, zero), index_a = code_a - (four * type_a);
    const auto b_is_face = code_b >= four;
    const batch index_b = code_b - xsimd::select(b_is_face, four, zero);
    const batch low_bytes = (index_a + (batch(0x1p8f) * type_a)) + (batch(0x1p16f) * index_b);
    static_assert(0x1p-125f == 1.17549435e-38f * 2.0f, "2^-125 has the bits 0x01000000");
    return xsimd::bitwise_or(integer_bits<Arch>(low_bytes), xsimd::select(b_is_face, batch(0x1p-125f), zero));
}

/// The contact of each lane's pair, as the reference's fields; the point
/// count and the feature keys hold the bits of their integers (integer_bits,
/// feature_bits).
template <class Arch>
struct contact_out_lanes {
    lanes<Arch> nx, ny, depth, count;
    lanes<Arch> x[2], y[2], separation[2], feature[2];
};

/// Step 2 for one box's faces against the other's vertices, and the argmax
/// fold: the separation, index, normal, its reciprocal length and the face's
/// ends of the best face.
template <class Arch>
struct best_face_lanes {
    lanes<Arch> sep, index, nx, ny, inv, x1, y1, x2, y2;
};

template <class Arch>
OBBSAT_LANE_INLINE best_face_lanes<Arch> best_face_lanes_of(const contact_box_lanes<Arch>& faces,
                                                             const contact_box_lanes<Arch>& other) {
    using batch = lanes<Arch>;
    best_face_lanes<Arch> best;
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
            best = best_face_lanes<Arch>{sep,         batch(0.0f),    faces.nx[0],    faces.ny[0], faces.inv[0],
                                         faces.vx[0], faces.vy[0], faces.vx[next], faces.vy[next]};
        } else {
            const auto better = sep > best.sep;
            best.sep = xsimd::select(better, sep, best.sep);
            best.index = xsimd::select(better, batch(static_cast<float>(k)), best.index);
            best.nx = xsimd::select(better, faces.nx[k], best.nx);
            best.ny = xsimd::select(better, faces.ny[k], best.ny);
            best.inv = xsimd::select(better, faces.inv[k], best.inv);
            best.x1 = xsimd::select(better, faces.vx[k], best.x1);
            best.y1 = xsimd::select(better, faces.vy[k], best.y1);
            best.x2 = xsimd::select(better, faces.vx[next], best.x2);
            best.y2 = xsimd::select(better, faces.vy[next], best.y2);
        }
    }
    return best;
}

/// Step 3's span of a box.
template <class Arch>
OBBSAT_LANE_INLINE lanes<Arch> span_lanes(const contact_box_lanes<Arch>& box) {
    lanes<Arch> lo_x = box.vx[0], hi_x = box.vx[0], lo_y = box.vy[0], hi_y = box.vy[0];
    for (int j = 1; j < 4; ++j) {
        lo_x = min_pick(box.vx[j], lo_x);
        hi_x = max_pick(box.vx[j], hi_x);
        lo_y = min_pick(box.vy[j], lo_y);
        hi_y = max_pick(box.vy[j], hi_y);
    }
    return max_pick(hi_x - lo_x, hi_y - lo_y);
}

/// Box b, or box a where `pick_a`.
template <class Arch>
OBBSAT_LANE_INLINE contact_box_lanes<Arch> either_box(const lane_mask<Arch>& pick_a, const contact_box_lanes<Arch>& a,
                                                      const contact_box_lanes<Arch>& b) {
    contact_box_lanes<Arch> out;
    for (int k = 0; k < 4; ++k) {
        out.vx[k] = xsimd::select(pick_a, a.vx[k], b.vx[k]);
        out.vy[k] = xsimd::select(pick_a, a.vy[k], b.vy[k]);
        out.nx[k] = xsimd::select(pick_a, a.nx[k], b.nx[k]);
        out.ny[k] = xsimd::select(pick_a, a.ny[k], b.ny[k]);
        out.inv[k] = xsimd::select(pick_a, a.inv[k], b.inv[k]);
    }
    return out;
}

/// What steps 1 to 3 choose, per lane: the reference box (B where flip), its
/// face r with its normal, that normal's reciprocal length and the face's
/// ends, and the best separations of A's and of B's faces.
template <class Arch>
struct reference_lanes {
    lane_mask<Arch> flip;
    lanes<Arch> r, sa, sb, nx, ny, inv, q1x, q1y, q2x, q2y;
};

/// Steps 1 to 3 of the reference for boxes a and b (the corner rule).
template <class Arch>
OBBSAT_LANE_INLINE reference_lanes<Arch> reference_of_boxes(const contact_box_lanes<Arch>& a,
                                                            const contact_box_lanes<Arch>& b) {
    // Step 2 (step 1 is the boxes' inv).
    const best_face_lanes<Arch> fa = best_face_lanes_of<Arch>(a, b);
    const best_face_lanes<Arch> fb = best_face_lanes_of<Arch>(b, a);
    // Step 3.
    const lanes<Arch> tol = lanes<Arch>(0x1p-10f) * min_pick(span_lanes<Arch>(a), span_lanes<Arch>(b));
    const auto flip = fb.sep > (fa.sep + tol);
    return reference_lanes<Arch>{flip,
                                 xsimd::select(flip, fb.index, fa.index),
                                 fa.sep,
                                 fb.sep,
                                 xsimd::select(flip, fb.nx, fa.nx),
                                 xsimd::select(flip, fb.ny, fa.ny),
                                 xsimd::select(flip, fb.inv, fa.inv),
                                 xsimd::select(flip, fb.x1, fa.x1),
                                 xsimd::select(flip, fb.y1, fa.y1),
                                 xsimd::select(flip, fb.x2, fa.x2),
                                 xsimd::select(flip, fb.y2, fa.y2)};
}

/// Step 4's normal and depth, with no point (count 0, every point field
/// zero): the contact of a pair whose best faces separate it by more than
/// the margin, and what steps 5 to 8 start from.
template <class Arch>
OBBSAT_LANE_INLINE contact_out_lanes<Arch> contact_without_points(const lane_mask<Arch>& flip,
                                                                  const lanes<Arch>& ux, const lanes<Arch>& uy,
                                                                  const lanes<Arch>& sa, const lanes<Arch>& sb) {
    const lanes<Arch> zero(0.0f);
    contact_out_lanes<Arch> out;
    out.nx = xsimd::select(flip, negated<Arch>(ux), ux);
    out.ny = xsimd::select(flip, negated<Arch>(uy), uy);
    out.depth = zero - xsimd::select(flip, sb, sa);
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
template <class Arch>
struct incident_edge_lanes {
    lanes<Arch> k, p1x, p1y, p2x, p2y;
};

/// Step 5 on a box of four faces: the face most against (ux, uy).
template <class Arch>
OBBSAT_LANE_INLINE incident_edge_lanes<Arch> incident_edge_of_box(const contact_box_lanes<Arch>& inc,
                                                                  const lanes<Arch>& ux, const lanes<Arch>& uy) {
    using batch = lanes<Arch>;
    incident_edge_lanes<Arch> edge;
    batch most_against;
    for (int f = 0; f < 4; ++f) {
        const int next = (f + 1) & 3;
        const batch along = ((inc.nx[f] * ux) + (inc.ny[f] * uy)) * inc.inv[f];
        const batch x1 = inc.vx[f], y1 = inc.vy[f], x2 = inc.vx[next], y2 = inc.vy[next];
        if (f == 0) {
            most_against = along;
            edge = incident_edge_lanes<Arch>{batch(0.0f), x1, y1, x2, y2};
        } else {
            const auto better = along < most_against;
            most_against = xsimd::select(better, along, most_against);
            edge.k = xsimd::select(better, batch(static_cast<float>(f)), edge.k);
            edge.p1x = xsimd::select(better, x1, edge.p1x);
            edge.p1y = xsimd::select(better, y1, edge.p1y);
            edge.p2x = xsimd::select(better, x2, edge.p2x);
            edge.p2y = xsimd::select(better, y2, edge.p2y);
        }
    }
    return edge;
}

/// Steps 6 to 8 of the reference, and step 4's outputs, from the reference
/// face (ref), its unit normal (ux, uy) and the incident edge.
template <class Arch>
OBBSAT_LANE_INLINE contact_out_lanes<Arch> clipped_manifold_lanes(const reference_lanes<Arch>& ref,
                                                                  const lanes<Arch>& ux, const lanes<Arch>& uy,
                                                                  const incident_edge_lanes<Arch>& edge,
                                                                  const lanes<Arch>& origin_x,
                                                                  const lanes<Arch>& origin_y, float margin_value) {
    using batch = lanes<Arch>;
    const batch zero(0.0f), one(1.0f), four(4.0f), margin(margin_value);
    const auto flip = ref.flip;
    const batch r = ref.r, q1x = ref.q1x, q1y = ref.q1y, q2x = ref.q2x, q2y = ref.q2y;
    const batch k = edge.k, p1x = edge.p1x, p1y = edge.p1y, p2x = edge.p2x, p2y = edge.p2y;

    contact_out_lanes<Arch> out = contact_without_points<Arch>(flip, ux, uy, ref.sa, ref.sb);

    // Step 6: clip to the side planes.
    const batch tx = q2x - q1x, ty = q2y - q1y;
    const batch T = (tx * tx) + (ty * ty);
    const batch tau[2] = {((p1x - q1x) * tx) + ((p1y - q1y) * ty), ((p2x - q1x) * tx) + ((p2y - q1y) * ty)};
    // Written without negating a mask: xsimd 8.1's AVX2 negation compares
    // masks through SSE2 halves, code that two per-ISA objects would share.
    const auto reaches_low_side = (tau[0] >= zero) | (tau[1] >= zero);
    const auto reaches_high_side = (tau[0] <= T) | (tau[1] <= T);
    const auto in_reach = (ref.sa <= margin) & (ref.sb <= margin) & reaches_low_side & reaches_high_side;
    const batch g = one / (tau[0] - tau[1]);
    const batch lambda_low = tau[0] * g, lambda_high = (tau[0] - T) * g;
    const batch along_x = p2x - p1x, along_y = p2y - p1y;
    const batch r_next = xsimd::select((r + one) == four, zero, r + one);
    const batch k_next = xsimd::select((k + one) == four, zero, k + one);
    const batch ex[2] = {p1x, p2x}, ey[2] = {p1y, p2y};
    const batch vertex_of_incident[2] = {k, k_next};

    batch px[2], py[2], sep[2], feature[2];
    lane_mask<Arch> keep[2];
    for (int e = 0; e < 2; ++e) {
        const auto below = tau[e] < zero;
        const auto moved = below | (tau[e] > T);
        const batch lambda = xsimd::select(below, lambda_low, lambda_high);
        px[e] = xsimd::select(moved, p1x + (lambda * along_x), ex[e]);
        py[e] = xsimd::select(moved, p1y + (lambda * along_y), ey[e]);
        // Step 8: feature codes, index + 4·type, face type 1.
        const batch ref_code = xsimd::select(moved, xsimd::select(below, r, r_next), r + four);
        const batch inc_code = xsimd::select(moved, k + four, vertex_of_incident[e]);
        feature[e] =
            feature_bits<Arch>(xsimd::select(flip, inc_code, ref_code), xsimd::select(flip, ref_code, inc_code));
        sep[e] = ((px[e] - q1x) * ux) + ((py[e] - q1y) * uy);
    }
    // Step 7: within the margin, or the nearer point of a touching or
    // overlapping pair; a kept separation above the margin reads as it.
    const auto touching = xsimd::select(flip, ref.sb, ref.sa) <= zero;
    for (int e = 0; e < 2; ++e) {
        keep[e] = in_reach & ((sep[e] <= margin) | (touching & (sep[e] <= sep[1 - e])));
    }
    for (int e = 0; e < 2; ++e) {
        sep[e] = xsimd::select(sep[e] <= margin, sep[e], margin);
    }
    // The second point only when it is not the first again.
    const auto repeats = keep[0] & (px[1] == px[0]) & (py[1] == py[0]);
    keep[1] = keep[1] & (xsimd::select(repeats, one, zero) == zero);
    // Kept points first, unused slots zero.
    const auto second_kept = keep[0] & keep[1];
    for (int e = 0; e < 2; ++e) {
        px[e] = origin_x + px[e];
        py[e] = origin_y + py[e];
    }
    out.x[0] = xsimd::select(keep[0], px[0], xsimd::select(keep[1], px[1], zero));
    out.y[0] = xsimd::select(keep[0], py[0], xsimd::select(keep[1], py[1], zero));
    out.separation[0] = xsimd::select(keep[0], sep[0], xsimd::select(keep[1], sep[1], zero));
    out.feature[0] = xsimd::select(keep[0], feature[0], xsimd::select(keep[1], feature[1], zero));
    out.x[1] = xsimd::select(second_kept, px[1], zero);
    out.y[1] = xsimd::select(second_kept, py[1], zero);
    out.separation[1] = xsimd::select(second_kept, sep[1], zero);
    out.feature[1] = xsimd::select(second_kept, feature[1], zero);
    out.count = integer_bits<Arch>(xsimd::select(keep[0], one, zero) + xsimd::select(keep[1], one, zero));
    return out;
}

/// Steps 4 to 8 of the reference from the choice of the reference face and
/// the incident box (B, or A where flip).
template <class Arch>
OBBSAT_LANE_INLINE contact_out_lanes<Arch> manifold_lanes_of(const contact_box_lanes<Arch>& inc,
                                                             const reference_lanes<Arch>& ref,
                                                             const lanes<Arch>& origin_x,
                                                             const lanes<Arch>& origin_y, float margin) {
    const lanes<Arch> ux = ref.nx * ref.inv, uy = ref.ny * ref.inv;
    return clipped_manifold_lanes<Arch>(ref, ux, uy, incident_edge_of_box<Arch>(inc, ux, uy), origin_x, origin_y,
                                        margin);
}

/// Face j's edge of pose boxes, per lane, without building the boxes: pose
/// fields cx, cy, hx, hy, c, s (f) relative to the origin, j a whole float 0
/// to 3. The reference's vertex k is ((ox ± ux) ± wx, (oy ± uy) ± wy) with
/// signs that depend on k alone; x − y is x + (−y) exactly, so each is written
/// as sums of the terms with their sign bits set: `a` on u for k = 0 and 3,
/// `b` on w for k = 0 and 1 (on wy the other way round). Face j's second end,
/// vertex j + 1, takes u's sign from the complement of b and w's from a.
template <class Arch>
OBBSAT_LANE_INLINE incident_edge_lanes<Arch> pose_edge_lanes(const lanes<Arch>* f, const lanes<Arch>& origin_x,
                                                             const lanes<Arch>& origin_y, const lanes<Arch>& j) {
    using batch = lanes<Arch>;
    const batch sign(-0.0f), none(0.0f);
    const batch ox = f[0] - origin_x, oy = f[1] - origin_y;
    const batch c = f[4], s = f[5];
    const batch ux = f[2] * c, uy = f[2] * s;
    const batch wx = f[3] * s, wy = f[3] * c;
    const batch a = xsimd::select((j == batch(0.0f)) | (j == batch(3.0f)), sign, none);
    const batch b = xsimd::select(j < batch(2.0f), sign, none);
    const batch not_a = xsimd::bitwise_xor(a, sign), not_b = xsimd::bitwise_xor(b, sign);
    auto signed_by = [](const batch& x, const batch& bit) { return xsimd::bitwise_xor(x, bit); };
    incident_edge_lanes<Arch> edge;
    edge.k = j;
    edge.p1x = (ox + signed_by(ux, a)) + signed_by(wx, b);
    edge.p1y = (oy + signed_by(uy, a)) + signed_by(wy, not_b);
    edge.p2x = (ox + signed_by(ux, not_b)) + signed_by(wx, a);
    edge.p2y = (oy + signed_by(uy, not_b)) + signed_by(wy, not_a);
    return edge;
}

/// What the pose steps P1 to P3 and step 4 choose, per lane: the reference
/// pose (B where flip), its face r, the best separations of A's and of B's
/// faces, the boxes' reciprocal lengths and the unit normal u of face r.
template <class Arch>
struct pose_reference_lanes {
    lane_mask<Arch> flip;
    lanes<Arch> r, sa, sb, inv_a, inv_b, ux, uy;
};

/// Pose steps P1 to P3 and step 4's normal for fields cx, cy, hx, hy, c, s of
/// A and of B.
template <class Arch>
OBBSAT_LANE_INLINE pose_reference_lanes<Arch> pose_reference_of(const lanes<Arch>* fa, const lanes<Arch>* fb) {
    using batch = lanes<Arch>;
    const batch zero(0.0f), one(1.0f), two(2.0f), three(3.0f);
    // Pose step 1.
    const batch len_a = xsimd::sqrt((fa[4] * fa[4]) + (fa[5] * fa[5]));
    const batch len_b = xsimd::sqrt((fb[4] * fb[4]) + (fb[5] * fb[5]));
    const batch inv_a = one / len_a, inv_b = one / len_b;

    // Pose step 2: method local's offsets and reaches.
    const pose_lanes<Arch> pa{fa[0], fa[1], fa[2], fa[3], fa[4], fa[5]};
    const pose_lanes<Arch> pb{fb[0], fb[1], fb[2], fb[3], fb[4], fb[5]};
    typename pose_steps<Arch>::axes axes;
    batch P, Q;
    pose_steps<Arch>::first_axes(pa, pb, axes, P, Q);
    pose_steps<Arch>::second_axes(pa, pb, axes, P, Q);
    batch sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (xsimd::abs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? inv_a : inv_b);
    }
    const auto a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    const batch sa = xsimd::select(a_on_y, sep[1], sep[0]), sb = xsimd::select(b_on_y, sep[3], sep[2]);

    // Pose step 3.
    const batch size_a = (fa[2] + fa[3]) * len_a, size_b = (fb[2] + fb[3]) * len_b;
    const batch tol = batch(0x1p-10f) * min_pick(size_a, size_b);
    const auto flip = sb > (sa + tol);

    // The face of the chosen axis that faces the other box.
    const batch r_a = xsimd::select(a_on_y, xsimd::select(axes.offset[1] >= zero, zero, two),
                                    xsimd::select(axes.offset[0] >= zero, one, three));
    const batch r_b = xsimd::select(b_on_y, xsimd::select(axes.offset[3] >= zero, two, zero),
                                    xsimd::select(axes.offset[2] >= zero, three, one));
    const batch r = xsimd::select(flip, r_b, r_a);
    // Step 4's normal: face r's of the reference pose, n = (−s, c), (c, s),
    // (s, −c), (−c, −s) for r = 0 to 3, only signs and places changing.
    const batch sign(-0.0f);
    const batch ref_c = xsimd::select(flip, fb[4], fa[4]), ref_s = xsimd::select(flip, fb[5], fa[5]);
    const auto odd = (r == one) | (r == three);
    const batch nx = xsimd::bitwise_xor(xsimd::select(odd, ref_c, ref_s),
                                        xsimd::select((r == zero) | (r == three), sign, zero));
    const batch ny = xsimd::bitwise_xor(xsimd::select(odd, ref_s, ref_c), xsimd::select(r >= two, sign, zero));
    const batch inv = xsimd::select(flip, inv_b, inv_a);
    return pose_reference_lanes<Arch>{flip, r, sa, sb, inv_a, inv_b, nx * inv, ny * inv};
}

/// Whether a lane's best faces leave its pair within the margin: only those
/// lanes can have points (step 7), the others are contact_without_points.
template <class Arch>
OBBSAT_LANE_INLINE lane_mask<Arch> may_have_points(const pose_reference_lanes<Arch>& p, float margin) {
    const lanes<Arch> limit(margin);
    return (p.sa <= limit) & (p.sb <= limit);
}

/// The contact of poses, per lane: fields cx, cy, hx, hy, c, s of A and of B
/// (the reference's pose steps, then steps 4 to 8).
template <class Arch>
OBBSAT_LANE_INLINE contact_out_lanes<Arch> contact_pose_lanes_of(const lanes<Arch>* fa, const lanes<Arch>* fb,
                                                                 float margin) {
    using batch = lanes<Arch>;
    const batch zero(0.0f);
    const batch origin_x = fa[0], origin_y = fa[1];
    const pose_reference_lanes<Arch> p = pose_reference_of<Arch>(fa, fb);
    const auto flip = p.flip;
    const batch r = p.r, ux = p.ux, uy = p.uy, inv_a = p.inv_a, inv_b = p.inv_b;


    // Step 5 on the incident pose: its faces' normals are ±(−s, c) and ±(c,
    // s), so faces 2 and 3 are along faces 0 and 1 negated (exactly: only
    // signs change, and a zero's sign does not change a strict compare).
    batch inc_fields[6], ref_fields[6];
    for (int f = 0; f < 6; ++f) {
        ref_fields[f] = xsimd::select(flip, fb[f], fa[f]);
        inc_fields[f] = xsimd::select(flip, fa[f], fb[f]);
    }
    const batch inc_inv = xsimd::select(flip, inv_a, inv_b);
    const batch inc_c = inc_fields[4], inc_s = inc_fields[5];
    const batch along_0 = ((negated<Arch>(inc_s) * ux) + (inc_c * uy)) * inc_inv;
    const batch along_1 = ((inc_c * ux) + (inc_s * uy)) * inc_inv;
    const batch along[4] = {along_0, along_1, negated<Arch>(along_0), negated<Arch>(along_1)};
    batch k = zero, most_against = along[0];
    for (int f = 1; f < 4; ++f) {
        const auto better = along[f] < most_against;
        most_against = xsimd::select(better, along[f], most_against);
        k = xsimd::select(better, batch(static_cast<float>(f)), k);
    }
    const incident_edge_lanes<Arch> edge = pose_edge_lanes<Arch>(inc_fields, origin_x, origin_y, k);
    const incident_edge_lanes<Arch> face = pose_edge_lanes<Arch>(ref_fields, origin_x, origin_y, r);
    // The normal and its reciprocal length: what steps 6 to 8 do not read again.
    const reference_lanes<Arch> ref{flip,     r,        p.sa,     p.sb,     ux,      uy,
                                    batch(1.0f), face.p1x, face.p1y, face.p2x, face.p2y};
    return clipped_manifold_lanes<Arch>(ref, ux, uy, edge, origin_x, origin_y, margin);
}

}  // namespace
}  // namespace obbsat::detail
