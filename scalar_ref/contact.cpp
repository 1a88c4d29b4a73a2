#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/local.hpp>

#include <cfloat>
#include <cmath>
#include <cstring>

namespace obbsat::ref {

namespace {

float dot(point p, point q) { return (p.x * q.x) + (p.y * q.y); }
float cross(point p, point q) { return (p.x * q.y) - (p.y * q.x); }
point minus(point p, point q) { return point{p.x - q.x, p.y - q.y}; }
float min_of(float u, float v) { return u < v ? u : v; }
float max_of(float u, float v) { return u > v ? u : v; }

const point& corner(const rect& r, int k) {
    const point* corners[4] = {&r.ul, &r.ur, &r.lr, &r.ll};
    return *corners[k];
}

/// Edge k of the quad as given: corner (k + 1) − corner k.
point edge(const rect& r, int k) { return minus(corner(r, (k + 1) & 3), corner(r, k)); }

bool normal_finite(float x) { return std::isfinite(x) && x >= FLT_MIN; }

/// Step 1: the reciprocal length of every face normal.
void inverse_lengths(const contact_box& box, float inv[4]) {
    for (int k = 0; k < 4; ++k) {
        inv[k] = 1.0f / std::sqrt(dot(box.n[k], box.n[k]));
    }
}

/// Step 2 for one box's faces against the other's vertices.
void face_separations(const contact_box& faces, const float inv[4], const contact_box& other, float sep[4]) {
    for (int k = 0; k < 4; ++k) {
        float least = dot(faces.n[k], minus(other.v[0], faces.v[k]));
        for (int j = 1; j < 4; ++j) {
            least = min_of(dot(faces.n[k], minus(other.v[j], faces.v[k])), least);
        }
        sep[k] = least * inv[k];
    }
}

/// The first index of the largest of four values.
int argmax(const float value[4]) {
    int best = 0;
    for (int k = 1; k < 4; ++k) {
        if (value[k] > value[best]) {
            best = k;
        }
    }
    return best;
}

/// Step 3: the larger side of the box's bounds.
float span(const contact_box& box) {
    float lo_x = box.v[0].x, hi_x = box.v[0].x, lo_y = box.v[0].y, hi_y = box.v[0].y;
    for (int j = 1; j < 4; ++j) {
        lo_x = min_of(box.v[j].x, lo_x);
        hi_x = max_of(box.v[j].x, hi_x);
        lo_y = min_of(box.v[j].y, lo_y);
        hi_y = max_of(box.v[j].y, hi_y);
    }
    return max_of(hi_x - lo_x, hi_y - lo_y);
}

contact_feature feature_of(bool flip, int ref_index, feature_type ref_type, int inc_index, feature_type inc_type) {
    const auto r = static_cast<std::uint8_t>(ref_index);
    const auto i = static_cast<std::uint8_t>(inc_index);
    return flip ? contact_feature{i, inc_type, r, ref_type} : contact_feature{r, ref_type, i, inc_type};
}

}  // namespace

contact_box contact_box_of(const rect_pose& p, point origin) {
    const float ox = p.center.x - origin.x, oy = p.center.y - origin.y;
    const float c = p.rotation.x, s = p.rotation.y;
    const float ux = p.half_extents.x * c, uy = p.half_extents.x * s;
    const float wx = p.half_extents.y * s, wy = p.half_extents.y * c;
    contact_box box;
    box.v[0] = point{(ox - ux) - wx, (oy - uy) + wy};
    box.v[1] = point{(ox + ux) - wx, (oy + uy) + wy};
    box.v[2] = point{(ox + ux) + wx, (oy + uy) - wy};
    box.v[3] = point{(ox - ux) + wx, (oy - uy) - wy};
    box.n[0] = point{-s, c};
    box.n[1] = point{c, s};
    box.n[2] = point{s, -c};
    box.n[3] = point{-c, -s};
    return box;
}

contact_box contact_box_of(const rect& r, point origin) {
    const bool clockwise = cross(edge(r, 0), edge(r, 1)) < 0.0f;
    contact_box box;
    for (int k = 0; k < 4; ++k) {
        box.v[k] = minus(corner(r, k), origin);
        const point e = edge(r, k);
        box.n[k] = clockwise ? point{-e.y, e.x} : point{e.y, -e.x};
    }
    return box;
}

bool corners_accepted(const rect& r) {
    int left = 0, right = 0;
    for (int k = 0; k < 4; ++k) {
        const point e = edge(r, k);
        if (!normal_finite(dot(e, e))) {
            return false;
        }
        const float turn = cross(e, edge(r, (k + 1) & 3));
        left += turn > 0.0f ? 1 : 0;
        right += turn < 0.0f ? 1 : 0;
    }
    return left == 4 || right == 4;
}

bool pose_accepted(const rect_pose& p) { return normal_finite(dot(p.rotation, p.rotation)); }

namespace {

/// What steps 1 to 3 choose: the reference box (B when flip), its face r,
/// and the best separations of A's and of B's faces.
struct reference_choice {
    bool flip;
    int r;
    float sa, sb;
};

/// Steps 4 to 8: the contact from the choice of the reference face.
contact manifold_of(const contact_box& a, const float inv_a[4], const contact_box& b, const float inv_b[4],
                    const reference_choice& choice, point origin, float margin) {
    const bool flip = choice.flip;
    const int r = choice.r;
    const float sa = choice.sa, sb = choice.sb;

    // Step 4: the reference face and the normal.
    const contact_box& ref = flip ? b : a;
    const contact_box& inc = flip ? a : b;
    const float* inc_inv = flip ? inv_a : inv_b;
    const float* ref_inv = flip ? inv_b : inv_a;
    const float sr = flip ? sb : sa;
    const point u{ref.n[r].x * ref_inv[r], ref.n[r].y * ref_inv[r]};

    contact out;
    std::memset(&out, 0, sizeof out);
    out.nx = flip ? -u.x : u.x;
    out.ny = flip ? -u.y : u.y;
    out.depth = 0.0f - sr;

    // Step 5: the incident edge, the face of I most against u.
    int k = 0;
    float most_against = dot(inc.n[0], u) * inc_inv[0];
    for (int f = 1; f < 4; ++f) {
        const float along = dot(inc.n[f], u) * inc_inv[f];
        if (along < most_against) {
            most_against = along;
            k = f;
        }
    }
    const point p1 = inc.v[k], p2 = inc.v[(k + 1) & 3];

    // Step 6: clip the edge to the reference face's side planes.
    const point q1 = ref.v[r], q2 = ref.v[(r + 1) & 3];
    const point t = minus(q2, q1);
    const float T = dot(t, t);
    const float tau[2] = {dot(minus(p1, q1), t), dot(minus(p2, q1), t)};
    const bool reaches_low_side = tau[0] >= 0.0f || tau[1] >= 0.0f;
    const bool reaches_high_side = tau[0] <= T || tau[1] <= T;
    if (!(sa <= margin && sb <= margin && reaches_low_side && reaches_high_side)) {
        return out;
    }
    const float g = 1.0f / (tau[0] - tau[1]);
    const point along = minus(p2, p1);
    const point ends[2] = {p1, p2};
    point at[2];
    contact_feature features[2];
    float separation[2];
    for (int e = 0; e < 2; ++e) {
        at[e] = ends[e];
        features[e] = feature_of(flip, r, feature_type::face, (k + e) & 3, feature_type::vertex);
        if (tau[e] < 0.0f || tau[e] > T) {
            const bool below = tau[e] < 0.0f;
            const float lambda = below ? tau[0] * g : (tau[0] - T) * g;
            at[e] = point{p1.x + (lambda * along.x), p1.y + (lambda * along.y)};
            features[e] = feature_of(flip, below ? r : (r + 1) & 3, feature_type::vertex, k, feature_type::face);
        }
        separation[e] = dot(minus(at[e], q1), u);
    }
    // Step 7: keep the points within the margin; a touching or overlapping
    // pair keeps its nearer point besides, since a separation of 0 exactly
    // can round to a few ulps above the margin 0 and drop both.
    const bool touching = sr <= 0.0f;
    point kept_at[2] = {};
    for (int e = 0; e < 2; ++e) {
        const bool nearer = separation[e] <= separation[1 - e];
        const bool within = separation[e] <= margin || (touching && nearer);
        const bool repeats = out.point_count == 1 && at[e].x == kept_at[0].x && at[e].y == kept_at[0].y;
        if (within && !repeats) {
            kept_at[out.point_count] = at[e];
            contact_point& kept = out.points[out.point_count++];
            kept.x = origin.x + at[e].x;
            kept.y = origin.y + at[e].y;
            kept.separation = separation[e] <= margin ? separation[e] : margin;
            kept.feature = features[e];
        }
    }
    return out;
}

}  // namespace

contact contact_of_boxes(const contact_box& a, const contact_box& b, point origin, float margin) {
    // Steps 1 and 2: the separation of every face, the best face of each box.
    float inv_a[4], inv_b[4], sep_a[4], sep_b[4];
    inverse_lengths(a, inv_a);
    inverse_lengths(b, inv_b);
    face_separations(a, inv_a, b, sep_a);
    face_separations(b, inv_b, a, sep_b);
    const int ia = argmax(sep_a), ib = argmax(sep_b);
    const float sa = sep_a[ia], sb = sep_b[ib];

    // Step 3: A's face unless B's separates clearly more.
    const float tol = 0x1p-10f * min_of(span(a), span(b));
    const bool flip = sb > (sa + tol);
    return manifold_of(a, inv_a, b, inv_b, reference_choice{flip, flip ? ib : ia, sa, sb}, origin, margin);
}

contact contact_of(const rect_pose& a, const rect_pose& b, float margin) {
    const point origin = a.center;
    const contact_box box_a = contact_box_of(a, origin), box_b = contact_box_of(b, origin);

    // Pose step 1: one reciprocal length per box.
    const float len_a = std::sqrt(dot(a.rotation, a.rotation)), len_b = std::sqrt(dot(b.rotation, b.rotation));
    const float inv_a = 1.0f / len_a, inv_b = 1.0f / len_b;
    const float inv_of_a[4] = {inv_a, inv_a, inv_a, inv_a}, inv_of_b[4] = {inv_b, inv_b, inv_b, inv_b};

    // Pose step 2: the separation on each of the four axes, from method
    // local's offsets and reaches (obbsat/ref/local.hpp).
    const pose_axes axes = local_axes(a, b);
    float sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (std::fabs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? inv_a : inv_b);
    }
    const bool a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    const float sa = a_on_y ? sep[1] : sep[0], sb = b_on_y ? sep[3] : sep[2];

    // Pose step 3: A's face unless B's separates clearly more.
    const float size_a = (a.half_extents.x + a.half_extents.y) * len_a;
    const float size_b = (b.half_extents.x + b.half_extents.y) * len_b;
    const float tol = 0x1p-10f * min_of(size_a, size_b);
    const bool flip = sb > (sa + tol);

    // The face of the chosen axis that faces the other box.
    int r = 0;
    if (!flip) {
        r = a_on_y ? (axes.offset[1] >= 0.0f ? 0 : 2) : (axes.offset[0] >= 0.0f ? 1 : 3);
    } else {
        r = b_on_y ? (axes.offset[3] >= 0.0f ? 2 : 0) : (axes.offset[2] >= 0.0f ? 3 : 1);
    }
    return manifold_of(box_a, inv_of_a, box_b, inv_of_b, reference_choice{flip, r, sa, sb}, origin, margin);
}

contact contact_of(const rect& a, const rect& b, float margin) {
    const point origin = a.ul;
    return contact_of_boxes(contact_box_of(a, origin), contact_box_of(b, origin), origin, margin);
}

}  // namespace obbsat::ref
