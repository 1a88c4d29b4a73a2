// The contact reference (obbsat/ref/contact.hpp), each step one template over
// the scalar type: float for the float boxes, double for the double ones.
#include "contact_shapes.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace obbsat::ref {

namespace {

using contact_steps::dot;
using contact_steps::minus;
using contact_steps::shapes;

template <class P>
auto cross(P p, P q) {
    return (p.x * q.y) - (p.y * q.x);
}
template <class T>
T min_of(T u, T v) {
    return u < v ? u : v;
}
template <class T>
T max_of(T u, T v) {
    return u > v ? u : v;
}

template <class Quad>
const auto& corner(const Quad& r, int k) {
    const decltype(r.ul)* corners[4] = {&r.ul, &r.ur, &r.lr, &r.ll};
    return *corners[k];
}

/// Edge k of the quad as given: corner (k + 1) − corner k.
template <class Quad>
auto edge(const Quad& r, int k) {
    return minus(corner(r, (k + 1) & 3), corner(r, k));
}

template <class T>
bool normal_finite(T x) {
    return std::isfinite(x) && x >= std::numeric_limits<T>::min();
}

/// Step 1: the reciprocal length of every face normal.
template <class T, class Box>
void inverse_lengths(const Box& box, T inv[4]) {
    for (int k = 0; k < 4; ++k) {
        inv[k] = T(1) / std::sqrt(dot(box.n[k], box.n[k]));
    }
}

/// Step 2 for one box's faces against the other's vertices.
template <class T, class Box>
void face_separations(const Box& faces, const T inv[4], const Box& other, T sep[4]) {
    for (int k = 0; k < 4; ++k) {
        T least = dot(faces.n[k], minus(other.v[0], faces.v[k]));
        for (int j = 1; j < 4; ++j) {
            least = min_of(dot(faces.n[k], minus(other.v[j], faces.v[k])), least);
        }
        sep[k] = least * inv[k];
    }
}

/// The first index of the largest of four values.
template <class T>
int argmax(const T value[4]) {
    int best = 0;
    for (int k = 1; k < 4; ++k) {
        if (value[k] > value[best]) {
            best = k;
        }
    }
    return best;
}

/// Step 3: the larger side of the box's bounds.
template <class Box>
auto span(const Box& box) {
    auto lo_x = box.v[0].x, hi_x = box.v[0].x, lo_y = box.v[0].y, hi_y = box.v[0].y;
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

template <class T>
typename shapes<T>::box pose_box(const typename shapes<T>::pose& p, typename shapes<T>::point_type origin) {
    using point_type = typename shapes<T>::point_type;
    const T ox = p.center.x - origin.x, oy = p.center.y - origin.y;
    const T c = p.rotation.x, s = p.rotation.y;
    const T ux = p.half_extents.x * c, uy = p.half_extents.x * s;
    const T wx = p.half_extents.y * s, wy = p.half_extents.y * c;
    typename shapes<T>::box box;
    box.v[0] = point_type{(ox - ux) - wx, (oy - uy) + wy};
    box.v[1] = point_type{(ox + ux) - wx, (oy + uy) + wy};
    box.v[2] = point_type{(ox + ux) + wx, (oy + uy) - wy};
    box.v[3] = point_type{(ox - ux) + wx, (oy - uy) - wy};
    box.n[0] = point_type{-s, c};
    box.n[1] = point_type{c, s};
    box.n[2] = point_type{s, -c};
    box.n[3] = point_type{-c, -s};
    return box;
}

template <class T>
typename shapes<T>::box quad_box(const typename shapes<T>::quad& r, typename shapes<T>::point_type origin) {
    using point_type = typename shapes<T>::point_type;
    const bool clockwise = cross(edge(r, 0), edge(r, 1)) < T(0);
    typename shapes<T>::box box;
    for (int k = 0; k < 4; ++k) {
        box.v[k] = minus(corner(r, k), origin);
        const point_type e = edge(r, k);
        box.n[k] = clockwise ? point_type{-e.y, e.x} : point_type{e.y, -e.x};
    }
    return box;
}

template <class T, class Quad>
bool quad_accepted(const Quad& r) {
    int left = 0, right = 0;
    for (int k = 0; k < 4; ++k) {
        const auto e = edge(r, k);
        if (!normal_finite<T>(dot(e, e))) {
            return false;
        }
        const T turn = cross(e, edge(r, (k + 1) & 3));
        left += turn > T(0) ? 1 : 0;
        right += turn < T(0) ? 1 : 0;
    }
    return left == 4 || right == 4;
}

/// What steps 1 to 3 choose: the reference box (B when flip), its face r,
/// and the best separations of A's and of B's faces.
template <class Real>
struct reference_choice {
    bool flip;
    int r;
    Real sa, sb;
};

/// Steps 4 to 8: the contact from the choice of the reference face.
template <class Real>
typename shapes<Real>::result manifold_of(const typename shapes<Real>::box& a, const Real inv_a[4],
                                          const typename shapes<Real>::box& b, const Real inv_b[4],
                                          const reference_choice<Real>& choice,
                                          typename shapes<Real>::point_type origin, Real margin) {
    using point_type = typename shapes<Real>::point_type;
    using box = typename shapes<Real>::box;
    const bool flip = choice.flip;
    const int r = choice.r;
    const Real sa = choice.sa, sb = choice.sb;

    // Step 4: the reference face and the normal.
    const box& ref = flip ? b : a;
    const box& inc = flip ? a : b;
    const Real* inc_inv = flip ? inv_a : inv_b;
    const Real* ref_inv = flip ? inv_b : inv_a;
    const Real sr = flip ? sb : sa;
    const point_type u{ref.n[r].x * ref_inv[r], ref.n[r].y * ref_inv[r]};

    typename shapes<Real>::result out;
    std::memset(&out, 0, sizeof out);
    out.nx = flip ? -u.x : u.x;
    out.ny = flip ? -u.y : u.y;
    out.depth = Real(0) - sr;

    // Step 5: the incident edge, the face of I most against u.
    int k = 0;
    Real most_against = dot(inc.n[0], u) * inc_inv[0];
    for (int f = 1; f < 4; ++f) {
        const Real along = dot(inc.n[f], u) * inc_inv[f];
        if (along < most_against) {
            most_against = along;
            k = f;
        }
    }
    const point_type p1 = inc.v[k], p2 = inc.v[(k + 1) & 3];

    // Step 6: clip the edge to the reference face's side planes.
    const point_type q1 = ref.v[r], q2 = ref.v[(r + 1) & 3];
    const point_type t = minus(q2, q1);
    const Real T = dot(t, t);
    const Real tau[2] = {dot(minus(p1, q1), t), dot(minus(p2, q1), t)};
    const bool reaches_low_side = tau[0] >= Real(0) || tau[1] >= Real(0);
    const bool reaches_high_side = tau[0] <= T || tau[1] <= T;
    if (!(sa <= margin && sb <= margin && reaches_low_side && reaches_high_side)) {
        return out;
    }
    const Real g = Real(1) / (tau[0] - tau[1]);
    const point_type along = minus(p2, p1);
    const point_type ends[2] = {p1, p2};
    point_type at[2];
    contact_feature features[2];
    Real separation[2];
    for (int e = 0; e < 2; ++e) {
        at[e] = ends[e];
        features[e] = feature_of(flip, r, feature_type::face, (k + e) & 3, feature_type::vertex);
        if (tau[e] < Real(0) || tau[e] > T) {
            const bool below = tau[e] < Real(0);
            const Real lambda = below ? tau[0] * g : (tau[0] - T) * g;
            at[e] = point_type{p1.x + (lambda * along.x), p1.y + (lambda * along.y)};
            features[e] = feature_of(flip, below ? r : (r + 1) & 3, feature_type::vertex, k, feature_type::face);
        }
        separation[e] = dot(minus(at[e], q1), u);
    }
    // Step 7: keep the points within the margin; a touching or overlapping
    // pair keeps its nearer point besides, since a separation of 0 exactly
    // can round to a few ulps above the margin 0 and drop both.
    const bool touching = sr <= Real(0);
    point_type kept_at[2] = {};
    for (int e = 0; e < 2; ++e) {
        const bool nearer = separation[e] <= separation[1 - e];
        const bool within = separation[e] <= margin || (touching && nearer);
        const bool repeats = out.point_count == 1 && at[e].x == kept_at[0].x && at[e].y == kept_at[0].y;
        if (within && !repeats) {
            kept_at[out.point_count] = at[e];
            auto& kept = out.points[out.point_count++];
            kept.x = origin.x + at[e].x;
            kept.y = origin.y + at[e].y;
            kept.separation = separation[e] <= margin ? separation[e] : margin;
            kept.feature = features[e];
        }
    }
    return out;
}

template <class Real>
typename shapes<Real>::result boxes_contact(const typename shapes<Real>::box& a, const typename shapes<Real>::box& b,
                                            typename shapes<Real>::point_type origin, Real margin) {
    // Steps 1 and 2: the separation of every face, the best face of each box.
    Real inv_a[4], inv_b[4], sep_a[4], sep_b[4];
    inverse_lengths(a, inv_a);
    inverse_lengths(b, inv_b);
    face_separations(a, inv_a, b, sep_a);
    face_separations(b, inv_b, a, sep_b);
    const int ia = argmax(sep_a), ib = argmax(sep_b);
    const Real sa = sep_a[ia], sb = sep_b[ib];

    // Step 3: A's face unless B's separates clearly more.
    const Real tol = Real(0x1p-10) * min_of(span(a), span(b));
    const bool flip = sb > (sa + tol);
    return manifold_of<Real>(a, inv_a, b, inv_b, reference_choice<Real>{flip, flip ? ib : ia, sa, sb}, origin,
                             margin);
}

template <class Real>
typename shapes<Real>::result poses_contact(const typename shapes<Real>::pose& a,
                                            const typename shapes<Real>::pose& b, Real margin) {
    const auto origin = a.center;
    const auto box_a = pose_box<Real>(a, origin), box_b = pose_box<Real>(b, origin);

    // Pose step 1: one reciprocal length per box.
    const Real len_a = std::sqrt(dot(a.rotation, a.rotation)), len_b = std::sqrt(dot(b.rotation, b.rotation));
    const Real inv_a = Real(1) / len_a, inv_b = Real(1) / len_b;
    const Real inv_of_a[4] = {inv_a, inv_a, inv_a, inv_a}, inv_of_b[4] = {inv_b, inv_b, inv_b, inv_b};

    // Pose step 2: the separation on each of the four axes, from method
    // local's offsets and reaches (obbsat/ref/local.hpp, local64.hpp).
    const auto axes = local_axes(a, b);
    Real sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (std::fabs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? inv_a : inv_b);
    }
    const bool a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    const Real sa = a_on_y ? sep[1] : sep[0], sb = b_on_y ? sep[3] : sep[2];

    // Pose step 3: A's face unless B's separates clearly more.
    const Real size_a = (a.half_extents.x + a.half_extents.y) * len_a;
    const Real size_b = (b.half_extents.x + b.half_extents.y) * len_b;
    const Real tol = Real(0x1p-10) * min_of(size_a, size_b);
    const bool flip = sb > (sa + tol);

    // The face of the chosen axis that faces the other box.
    int r = 0;
    if (!flip) {
        r = a_on_y ? (axes.offset[1] >= Real(0) ? 0 : 2) : (axes.offset[0] >= Real(0) ? 1 : 3);
    } else {
        r = b_on_y ? (axes.offset[3] >= Real(0) ? 2 : 0) : (axes.offset[2] >= Real(0) ? 3 : 1);
    }
    return manifold_of<Real>(box_a, inv_of_a, box_b, inv_of_b, reference_choice<Real>{flip, r, sa, sb}, origin,
                             margin);
}

template <class Real>
typename shapes<Real>::result quads_contact(const typename shapes<Real>::quad& a,
                                            const typename shapes<Real>::quad& b, Real margin) {
    const auto origin = a.ul;
    return boxes_contact<Real>(quad_box<Real>(a, origin), quad_box<Real>(b, origin), origin, margin);
}

}  // namespace

contact_box contact_box_of(const rect_pose& p, point origin) { return pose_box<float>(p, origin); }
contact_box64 contact_box_of(const rect_pose64& p, point64 origin) { return pose_box<double>(p, origin); }
contact_box contact_box_of(const rect& r, point origin) { return quad_box<float>(r, origin); }
contact_box64 contact_box_of(const rect64& r, point64 origin) { return quad_box<double>(r, origin); }

bool corners_accepted(const rect& r) { return quad_accepted<float>(r); }
bool corners_accepted(const rect64& r) { return quad_accepted<double>(r); }
bool pose_accepted(const rect_pose& p) { return normal_finite(dot(p.rotation, p.rotation)); }
bool pose_accepted(const rect_pose64& p) { return normal_finite(dot(p.rotation, p.rotation)); }

contact contact_of_boxes(const contact_box& a, const contact_box& b, point origin, float margin) {
    return boxes_contact<float>(a, b, origin, margin);
}
contact64 contact_of_boxes(const contact_box64& a, const contact_box64& b, point64 origin, double margin) {
    return boxes_contact<double>(a, b, origin, margin);
}

contact contact_of(const rect_pose& a, const rect_pose& b, float margin) { return poses_contact<float>(a, b, margin); }
contact64 contact_of(const rect_pose64& a, const rect_pose64& b, double margin) {
    return poses_contact<double>(a, b, margin);
}
contact contact_of(const rect& a, const rect& b, float margin) { return quads_contact<float>(a, b, margin); }
contact64 contact_of(const rect64& a, const rect64& b, double margin) { return quads_contact<double>(a, b, margin); }

}  // namespace obbsat::ref
