#include "contact_exact.hpp"

namespace obbsat::accuracy {

namespace {

// Every mpf value made here, and by a caller from these, gets the bits the
// header promises (mpf_class's default would be 64).
[[maybe_unused]] const bool default_bits_set = (mpf_set_default_prec(contact_exact_bits), true);

/// Every float and every double is a dyadic rational, held here exactly.
mpq_class exact(double v) { return mpq_class(v); }
mpq_class dot(const exact_point& p, const exact_point& q) { return p.x * q.x + p.y * q.y; }
mpq_class cross(const exact_point& p, const exact_point& q) { return p.x * q.y - p.y * q.x; }
exact_point minus(const exact_point& p, const exact_point& q) { return exact_point{p.x - q.x, p.y - q.y}; }
template <class Point>
exact_point exact_of(Point p) {
    return exact_point{exact(p.x), exact(p.y)};
}

mpf_class mpf(const mpq_class& q) { return mpf_class(q, contact_exact_bits); }
mpf_class root(const mpq_class& q) { return sqrt(mpf(q)); }

/// The sign of x1/√n1 − x2/√n2 (n1, n2 > 0), exactly.
int compare_scaled(const mpq_class& x1, const mpq_class& n1, const mpq_class& x2, const mpq_class& n2) {
    const int s1 = sgn(x1), s2 = sgn(x2);
    if (s1 != s2) {
        return s1 > s2 ? 1 : -1;
    }
    if (s1 == 0) {
        return 0;
    }
    const int magnitude = cmp(x1 * x1 * n2, x2 * x2 * n1);
    return s1 > 0 ? magnitude : -magnitude;
}

/// x/√n2 <= m for m >= 0, exactly.
bool at_most(const mpq_class& x, const mpq_class& n2, const mpq_class& m) {
    return sgn(x) <= 0 || x * x <= m * m * n2;
}

/// The least signed distance (times √n2) of `other`'s vertices beyond face k of `faces`.
mpq_class face_separation(const exact_box& faces, int k, const exact_box& other) {
    mpq_class least = dot(faces.n[k], minus(other.v[0], faces.v[k]));
    for (int j = 1; j < 4; ++j) {
        const mpq_class d = dot(faces.n[k], minus(other.v[j], faces.v[k]));
        if (d < least) {
            least = d;
        }
    }
    return least;
}

/// Step 2's argmax: the first face of largest separation.
int best_face(const exact_box& faces, const exact_box& other, mpq_class& separation) {
    int best = 0;
    separation = face_separation(faces, 0, other);
    for (int k = 1; k < 4; ++k) {
        const mpq_class s = face_separation(faces, k, other);
        if (compare_scaled(s, faces.n2[k], separation, faces.n2[best]) > 0) {
            best = k;
            separation = s;
        }
    }
    return best;
}

mpq_class span(const exact_box& box) {
    mpq_class lo_x = box.v[0].x, hi_x = box.v[0].x, lo_y = box.v[0].y, hi_y = box.v[0].y;
    for (int j = 1; j < 4; ++j) {
        lo_x = box.v[j].x < lo_x ? box.v[j].x : lo_x;
        hi_x = box.v[j].x > hi_x ? box.v[j].x : hi_x;
        lo_y = box.v[j].y < lo_y ? box.v[j].y : lo_y;
        hi_y = box.v[j].y > hi_y ? box.v[j].y : hi_y;
    }
    const mpq_class wide = hi_x - lo_x, tall = hi_y - lo_y;
    return wide > tall ? wide : tall;
}

contact_feature feature_of(bool flip, int ref_index, feature_type ref_type, int inc_index, feature_type inc_type) {
    const auto r = static_cast<std::uint8_t>(ref_index);
    const auto i = static_cast<std::uint8_t>(inc_index);
    return flip ? contact_feature{i, inc_type, r, ref_type} : contact_feature{r, ref_type, i, inc_type};
}

}  // namespace

mpf_class value_of(const scaled_value& s) { return mpf(s.x) / root(s.n2); }

namespace {

// The float and double inputs take the same steps: only the type of the
// values read differs, and each is read exactly.
template <class Pose>
exact_box box_of_pose(const Pose& p) {
    const mpq_class cx = exact(p.center.x), cy = exact(p.center.y);
    const mpq_class c = exact(p.rotation.x), s = exact(p.rotation.y);
    const mpq_class ux = exact(p.half_extents.x) * c, uy = exact(p.half_extents.x) * s;
    const mpq_class wx = exact(p.half_extents.y) * s, wy = exact(p.half_extents.y) * c;
    exact_box box;
    box.v[0] = exact_point{cx - ux - wx, cy - uy + wy};
    box.v[1] = exact_point{cx + ux - wx, cy + uy + wy};
    box.v[2] = exact_point{cx + ux + wx, cy + uy - wy};
    box.v[3] = exact_point{cx - ux + wx, cy - uy - wy};
    box.n[0] = exact_point{-s, c};
    box.n[1] = exact_point{c, s};
    box.n[2] = exact_point{s, -c};
    box.n[3] = exact_point{-c, -s};
    for (int k = 0; k < 4; ++k) {
        box.n2[k] = dot(box.n[k], box.n[k]);
    }
    return box;
}

template <class Quad>
bool box_of_quad(const Quad& r, exact_box& out) {
    const decltype(r.ul) corners[4] = {r.ul, r.ur, r.lr, r.ll};
    exact_point e[4];
    for (int k = 0; k < 4; ++k) {
        out.v[k] = exact_of(corners[k]);
    }
    for (int k = 0; k < 4; ++k) {
        e[k] = minus(out.v[(k + 1) & 3], out.v[k]);
    }
    int left = 0, right = 0;
    for (int k = 0; k < 4; ++k) {
        const int turn = sgn(cross(e[k], e[(k + 1) & 3]));
        left += turn > 0 ? 1 : 0;
        right += turn < 0 ? 1 : 0;
    }
    if (left != 4 && right != 4) {
        return false;
    }
    const bool clockwise = right == 4;
    for (int k = 0; k < 4; ++k) {
        out.n[k] = clockwise ? exact_point{-e[k].y, e[k].x} : exact_point{e[k].y, -e[k].x};
        out.n2[k] = dot(out.n[k], out.n[k]);
    }
    return true;
}

template <class Pose>
exact_choice choice_of_poses(const Pose& a, const Pose& b) {
    // P2: local's offsets and reaches (obbsat/ref/local.hpp), exact.
    const mpq_class dx = exact(b.center.x) - exact(a.center.x), dy = exact(b.center.y) - exact(a.center.y);
    const mpq_class ca = exact(a.rotation.x), sa = exact(a.rotation.y);
    const mpq_class cb = exact(b.rotation.x), sb = exact(b.rotation.y);
    const mpq_class p = ca * cb + sa * sb, q = ca * sb - sa * cb;
    const mpq_class P = abs(p), Q = abs(q);
    const mpq_class na = ca * ca + sa * sa, nb = cb * cb + sb * sb;
    const mpq_class hxa = exact(a.half_extents.x), hya = exact(a.half_extents.y);
    const mpq_class hxb = exact(b.half_extents.x), hyb = exact(b.half_extents.y);
    const mpq_class w[4] = {dx * ca + dy * sa, dy * ca - dx * sa, dx * cb + dy * sb, dy * cb - dx * sb};
    const mpq_class reach[4] = {hxa * na + hxb * P + hyb * Q, hya * na + hxb * Q + hyb * P,
                                hxb * nb + hxa * P + hya * Q, hyb * nb + hxa * Q + hya * P};
    mpq_class sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = abs(w[k]) - reach[k];
    }
    const bool a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    exact_choice out;
    out.sa = scaled_value{a_on_y ? sep[1] : sep[0], na};
    out.sb = scaled_value{b_on_y ? sep[3] : sep[2], nb};

    // P3: A's face unless B's separates clearly more.
    const mpf_class size_a = mpf(hxa + hya) * root(na), size_b = mpf(hxb + hyb) * root(nb);
    const mpf_class tol = mpf(mpq_class(1, 1024)) * (size_a < size_b ? size_a : size_b);
    const bool flip = value_of(out.sb) > value_of(out.sa) + tol;
    int r = 0;
    if (!flip) {
        r = a_on_y ? (w[1] >= 0 ? 0 : 2) : (w[0] >= 0 ? 1 : 3);
    } else {
        r = b_on_y ? (w[3] >= 0 ? 2 : 0) : (w[2] >= 0 ? 3 : 1);
    }
    out.face = face_choice{flip, r};
    return out;
}

}  // namespace

exact_box exact_box_of(const rect_pose& p) { return box_of_pose(p); }
exact_box exact_box_of(const rect_pose64& p) { return box_of_pose(p); }
bool exact_box_of(const rect& r, exact_box& out) { return box_of_quad(r, out); }
bool exact_box_of(const rect64& r, exact_box& out) { return box_of_quad(r, out); }
exact_choice exact_choice_of(const rect_pose& a, const rect_pose& b) { return choice_of_poses(a, b); }
exact_choice exact_choice_of(const rect_pose64& a, const rect_pose64& b) { return choice_of_poses(a, b); }

exact_choice exact_choice_of(const exact_box& a, const exact_box& b) {
    exact_choice out;
    const int ia = best_face(a, b, out.sa.x);
    const int ib = best_face(b, a, out.sb.x);
    out.sa.n2 = a.n2[ia];
    out.sb.n2 = b.n2[ib];
    const mpq_class span_a = span(a), span_b = span(b);
    const mpq_class tol = mpq_class(1, 1024) * (span_a < span_b ? span_a : span_b);
    const bool flip = value_of(out.sb) > value_of(out.sa) + mpf(tol);
    out.face = face_choice{flip, flip ? ib : ia};
    return out;
}

exact_contact exact_contact_of(const exact_box& a, const exact_box& b, const exact_choice& choice,
                               const face_choice& face, double margin, int incident) {
    const bool flip = face.flip;
    const int r = face.r;
    const exact_box& ref = flip ? b : a;
    const exact_box& inc = flip ? a : b;
    const mpq_class m = exact(margin);

    // Step 4: the normal of face r, the depth from that face's separation.
    exact_contact out;
    out.face = face;
    const mpf_class length = root(ref.n2[r]);
    const mpf_class ux = mpf(ref.n[r].x) / length, uy = mpf(ref.n[r].y) / length;
    out.nx = flip ? mpf_class(-ux) : ux;
    out.ny = flip ? mpf_class(-uy) : uy;
    out.depth = -(mpf(face_separation(ref, r, inc)) / length);

    // Step 5: the incident face, most against the normal (first by strict <).
    int k = 0;
    mpq_class most_against = dot(inc.n[0], ref.n[r]);
    for (int f = 1; f < 4; ++f) {
        const mpq_class along = dot(inc.n[f], ref.n[r]);
        if (compare_scaled(along, inc.n2[f], most_against, inc.n2[k]) < 0) {
            k = f;
            most_against = along;
        }
    }
    k = incident >= 0 ? incident : k;
    out.incident = k;
    const exact_point p1 = inc.v[k], p2 = inc.v[(k + 1) & 3];

    // Step 6: clip to the side planes of face r.
    const exact_point q1 = ref.v[r], q2 = ref.v[(r + 1) & 3];
    const exact_point t = minus(q2, q1);
    const mpq_class T = dot(t, t);
    const mpq_class tau[2] = {dot(minus(p1, q1), t), dot(minus(p2, q1), t)};
    if (T > 0) {
        const mpq_class distances[4] = {abs(tau[0]), abs(tau[1]), abs(tau[0] - T), abs(tau[1] - T)};
        mpq_class least = distances[0];
        for (const mpq_class& d : distances) {
            least = d < least ? d : least;
        }
        out.side_distance = mpf(least) / root(T);
    }
    const bool reaches_low_side = tau[0] >= 0 || tau[1] >= 0;
    const bool reaches_high_side = tau[0] <= T || tau[1] <= T;
    if (!(at_most(choice.sa.x, choice.sa.n2, m) && at_most(choice.sb.x, choice.sb.n2, m) && reaches_low_side &&
          reaches_high_side)) {
        return out;
    }
    const exact_point along = minus(p2, p1);
    const exact_point ends[2] = {p1, p2};
    for (int e = 0; e < 2; ++e) {
        exact_point p = ends[e];
        contact_feature feature = feature_of(flip, r, feature_type::face, (k + e) & 3, feature_type::vertex);
        if (tau[e] < 0 || tau[e] > T) {
            const bool below = tau[e] < 0;
            const mpq_class lambda = (below ? tau[0] : mpq_class(tau[0] - T)) / (tau[0] - tau[1]);
            p = exact_point{p1.x + lambda * along.x, p1.y + lambda * along.y};
            feature = feature_of(flip, below ? r : (r + 1) & 3, feature_type::vertex, k, feature_type::face);
        }
        // Step 7: within the margin, and not the point already kept.
        const mpq_class separation = dot(minus(p, q1), ref.n[r]);
        out.end_separation[e] = mpf(separation) / length;
        out.ends = e + 1;
        const bool repeats = out.point_count == 1 && p.x == out.points[0].p.x && p.y == out.points[0].p.y;
        if (at_most(separation, ref.n2[r], m) && !repeats) {
            exact_contact_point& kept = out.points[out.point_count++];
            kept.p = p;
            kept.separation = mpf(separation) / length;
            kept.feature = feature;
        }
    }
    return out;
}

}  // namespace obbsat::accuracy
