#include "contact_error.hpp"

#include <obbsat/contact.hpp>
#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/local.hpp>
#include <obbsat/ref/local64.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace obbsat::accuracy {

namespace {

// The rounded reference's steps 1 to 3 (P1 to P3 on poses), as its header
// states them, in float or in double (T): which face it takes as the
// reference. The contact does not say so when it has no points; the
// measurement checks that the normal it gives is this face's, bit for bit, so
// the two cannot drift apart.
template <class P>
auto dot(P p, P q) {
    return (p.x * q.x) + (p.y * q.y);
}
// min and max as the reference folds them (the second value on a tie).
template <class T> T min_of(T u, T v) { return u < v ? u : v; }
template <class T> T max_of(T u, T v) { return u > v ? u : v; }

struct rounded_choice {
    face_choice face;
    int incident;    // step 5's face of the incident box
    double nx, ny;   // the normal it gives (a float's value when T is float)
};

/// Step 5: the incident box's face most against u = (ux, uy), the first by strict <.
template <class Box, class T>
int incident_face(const Box& inc, const T inc_inv[4], T ux, T uy) {
    using point_type = decltype(inc.n[0]);
    int k = 0;
    T most_against = dot(inc.n[0], point_type{ux, uy}) * inc_inv[0];
    for (int f = 1; f < 4; ++f) {
        const T along = dot(inc.n[f], point_type{ux, uy}) * inc_inv[f];
        if (along < most_against) {
            most_against = along;
            k = f;
        }
    }
    return k;
}

template <class Pose>
rounded_choice rounded_choice_of_poses(const Pose& a, const Pose& b) {
    using T = decltype(a.center.x);
    const T len_a = std::sqrt(dot(a.rotation, a.rotation)), len_b = std::sqrt(dot(b.rotation, b.rotation));
    const T inv_a = T(1) / len_a, inv_b = T(1) / len_b;
    const auto axes = ref::local_axes(a, b);
    T sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (std::fabs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? inv_a : inv_b);
    }
    const bool a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    const T sa = a_on_y ? sep[1] : sep[0], sb = b_on_y ? sep[3] : sep[2];
    const T size_a = (a.half_extents.x + a.half_extents.y) * len_a;
    const T size_b = (b.half_extents.x + b.half_extents.y) * len_b;
    const bool flip = sb > (sa + static_cast<T>(0x1p-10) * min_of(size_a, size_b));
    int r = 0;
    if (!flip) {
        r = a_on_y ? (axes.offset[1] >= T(0) ? 0 : 2) : (axes.offset[0] >= T(0) ? 1 : 3);
    } else {
        r = b_on_y ? (axes.offset[3] >= T(0) ? 2 : 0) : (axes.offset[2] >= T(0) ? 3 : 1);
    }
    const auto ref_box = ref::contact_box_of(flip ? b : a, a.center);
    const auto inc_box = ref::contact_box_of(flip ? a : b, a.center);
    const T inv = flip ? inv_b : inv_a;
    const T inc_inv[4] = {flip ? inv_a : inv_b, flip ? inv_a : inv_b, flip ? inv_a : inv_b, flip ? inv_a : inv_b};
    const T ux = ref_box.n[r].x * inv, uy = ref_box.n[r].y * inv;
    return rounded_choice{face_choice{flip, r}, incident_face(inc_box, inc_inv, ux, uy), flip ? -ux : ux,
                          flip ? -uy : uy};
}

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

template <class Box, class T>
int best_face(const Box& faces, const T inv[4], const Box& other, T& best_sep) {
    using point_type = std::remove_const_t<std::remove_reference_t<decltype(faces.v[0])>>;
    int best = 0;
    for (int k = 0; k < 4; ++k) {
        const point_type d0{other.v[0].x - faces.v[k].x, other.v[0].y - faces.v[k].y};
        T least = dot(faces.n[k], d0);
        for (int j = 1; j < 4; ++j) {
            const point_type d{other.v[j].x - faces.v[k].x, other.v[j].y - faces.v[k].y};
            least = min_of(dot(faces.n[k], d), least);
        }
        const T sep = least * inv[k];
        if (k == 0 || sep > best_sep) {
            best = k;
            best_sep = sep;
        }
    }
    return best;
}

template <class Quad>
rounded_choice rounded_choice_of_quads(const Quad& a, const Quad& b) {
    using T = decltype(a.ul.x);
    const auto box_a = ref::contact_box_of(a, a.ul), box_b = ref::contact_box_of(b, a.ul);
    T inv_a[4], inv_b[4];
    for (int k = 0; k < 4; ++k) {
        inv_a[k] = T(1) / std::sqrt(dot(box_a.n[k], box_a.n[k]));
        inv_b[k] = T(1) / std::sqrt(dot(box_b.n[k], box_b.n[k]));
    }
    T sa = 0, sb = 0;
    const int ia = best_face(box_a, inv_a, box_b, sa), ib = best_face(box_b, inv_b, box_a, sb);
    const bool flip = sb > (sa + static_cast<T>(0x1p-10) * min_of(span(box_a), span(box_b)));
    const int r = flip ? ib : ia;
    const auto& ref_box = flip ? box_b : box_a;
    const T inv = flip ? inv_b[r] : inv_a[r];
    const T ux = ref_box.n[r].x * inv, uy = ref_box.n[r].y * inv;
    const int k = flip ? incident_face(box_a, inv_a, ux, uy) : incident_face(box_b, inv_b, ux, uy);
    return rounded_choice{face_choice{flip, r}, k, flip ? -ux : ux, flip ? -uy : uy};
}

double to_double(const mpf_class& v) { return v.get_d(); }
mpf_class mpf_of(double v) { return mpf_class(v, contact_exact_bits); }
mpf_class mpf_of(const mpq_class& v) { return mpf_class(v, contact_exact_bits); }

/// The angle between the rounded normal and the exact one.
template <class Contact>
double angle_between(const Contact& c, const exact_contact& e) {
    const mpf_class fx = mpf_of(c.nx), fy = mpf_of(c.ny);
    const mpf_class sine = fx * e.ny - fy * e.nx, cosine = fx * e.nx + fy * e.ny;
    return std::atan2(std::fabs(to_double(sine)), to_double(cosine));
}

template <class ContactPoint>
double point_distance(const ContactPoint& p, const exact_point& q) {
    const mpf_class dx = mpf_of(p.x) - mpf_of(q.x), dy = mpf_of(p.y) - mpf_of(q.y);
    return std::hypot(to_double(dx), to_double(dy));
}

template <class Point>
double largest_coordinate(const exact_box& box, Point origin) {
    double reach = 0;
    for (const exact_point& v : box.v) {
        reach = std::max(reach, std::fabs(mpq_class(v.x - mpq_class(static_cast<double>(origin.x))).get_d()));
        reach = std::max(reach, std::fabs(mpq_class(v.y - mpq_class(static_cast<double>(origin.y))).get_d()));
    }
    return reach;
}

/// The part shared by poses and corners, once both boxes and choices are known.
template <class Contact, class Point>
pair_errors measure(const Contact& c, const rounded_choice& chosen, const exact_box& a, const exact_box& b,
                    const exact_choice& exact, Point origin, double size) {
    pair_errors out;
    out.measured = true;
    out.unit = std::numeric_limits<decltype(c.nx)>::epsilon() / 2;
    out.size = size;
    out.reach = std::max(largest_coordinate(a, origin), largest_coordinate(b, origin));
    out.offset = std::max(std::fabs(static_cast<double>(origin.x)), std::fabs(static_cast<double>(origin.y)));
    out.choice_matches_normal = chosen.nx == c.nx && chosen.ny == c.ny;

    // The exact result of the float reference's choices: its reference face
    // and its incident face (which differs from the exact step 5 only near a
    // tie of two incident faces, e.g. a square's two edges at 45°).
    const exact_contact same = exact_contact_of(a, b, exact, chosen.face, 0.0f, chosen.incident);
    out.incident_differs = exact_contact_of(a, b, exact, chosen.face).incident != chosen.incident;
    out.normal_angle = angle_between(c, same);
    out.depth_error = std::fabs(to_double(mpf_of(c.depth) - same.depth));
    out.count_differs = static_cast<int>(c.point_count) != same.point_count;
    if (!out.count_differs) {
        for (int k = 0; k < same.point_count; ++k) {
            out.point_error = std::max(out.point_error, point_distance(c.points[k], same.points[k].p));
            out.separation_error = std::max(
                out.separation_error, std::fabs(to_double(mpf_of(c.points[k].separation) - same.points[k].separation)));
        }
    } else {
        double boundary = std::min(std::fabs(to_double(value_of(exact.sa))), std::fabs(to_double(value_of(exact.sb))));
        for (int e = 0; e < same.ends; ++e) {
            boundary = std::min(boundary, std::fabs(to_double(same.end_separation[e])));
        }
        boundary = std::min(boundary, std::fabs(to_double(same.side_distance)));
        if (same.point_count == 2) {
            const mpf_class dx = mpf_of(same.points[0].p.x - same.points[1].p.x);
            const mpf_class dy = mpf_of(same.points[0].p.y - same.points[1].p.y);
            boundary = std::min(boundary, std::hypot(to_double(dx), to_double(dy)));
        }
        out.count_boundary = boundary / (out.unit * out.reach);
    }

    out.choice_differs = exact.face != chosen.face;
    if (out.choice_differs) {
        const exact_contact truth = exact_contact_of(a, b, exact, exact.face);
        out.normal_angle_exact_choice = angle_between(c, truth);
        out.depth_error_exact_choice = std::fabs(to_double(mpf_of(c.depth) - truth.depth));
        out.count_differs_exact_choice = static_cast<int>(c.point_count) != truth.point_count;
    }
    return out;
}

template <class Contact, class Pose>
pair_errors measure_pose_contact(const Pose& a, const Pose& b, const Contact& c) {
    const exact_box box_a = exact_box_of(a), box_b = exact_box_of(b);
    double size = 0;
    for (const Pose* p : {&a, &b}) {
        const double length = std::hypot(static_cast<double>(p->rotation.x), static_cast<double>(p->rotation.y));
        size = std::max({size, p->half_extents.x * length, p->half_extents.y * length});
    }
    return measure(c, rounded_choice_of_poses(a, b), box_a, box_b, exact_choice_of(a, b), a.center, size);
}

/// Whether the quads' contact is defined (the reference accepts both) and
/// measurable (both strictly convex in exact arithmetic too).
template <class Quad>
bool quads_measurable(const Quad& a, const Quad& b, exact_box& box_a, exact_box& box_b) {
    return ref::corners_accepted(a) && ref::corners_accepted(b) && exact_box_of(a, box_a) && exact_box_of(b, box_b);
}

template <class Contact, class Quad>
pair_errors measure_quad_contact(const Quad& a, const Quad& b, const Contact& c) {
    exact_box box_a, box_b;
    if (!quads_measurable(a, b, box_a, box_b)) {
        return pair_errors{};
    }
    double size = 0;
    for (const exact_box* box : {&box_a, &box_b}) {
        for (int k = 0; k < 4; ++k) {
            size = std::max(size, std::sqrt(box->n2[k].get_d()) / 2);
        }
    }
    return measure(c, rounded_choice_of_quads(a, b), box_a, box_b, exact_choice_of(box_a, box_b), a.ul, size);
}

}  // namespace

pair_errors measure_poses(const rect_pose& a, const rect_pose& b) {
    return measure_pose_contact(a, b, ref::contact_of(a, b));
}

pair_errors measure_corners(const rect& a, const rect& b) {
    exact_box box_a, box_b;
    if (!quads_measurable(a, b, box_a, box_b)) {
        return pair_errors{};
    }
    return measure_quad_contact(a, b, ref::contact_of(a, b));
}

pair_errors measure_poses(const rect_pose64& a, const rect_pose64& b, const contact64& c) {
    return measure_pose_contact(a, b, c);
}

pair_errors measure_corners(const rect64& a, const rect64& b, const contact64& c) {
    return measure_quad_contact(a, b, c);
}

bool corners_measurable(const rect64& a, const rect64& b) {
    exact_box box_a, box_b;
    return quads_measurable(a, b, box_a, box_b);
}

double_contacts contacts_through_the_api(const std::vector<pose_pair64>& pairs) {
    double_contacts out;
    pose_records64 a, b;
    rect_records64 quads_a, quads_b;
    for (const pose_pair64& pair : pairs) {
        a.push_back(pair.a);
        b.push_back(pair.b);
        const rect64 qa = corners_of(pair.a), qb = corners_of(pair.b);
        // The entry points refuse a batch holding a quad they do not accept:
        // only the measurable corner forms go in, the others get no contact.
        const bool measurable = corners_measurable(qa, qb);
        out.corners_measured.push_back(measurable);
        if (measurable) {
            quads_a.push_back(qa);
            quads_b.push_back(qb);
        }
    }
    out.poses.resize(pairs.size());
    out.corners.resize(quads_a.size());
    contact_stream(a, b, out.poses.data());
    contact_stream(quads_a, quads_b, out.corners.data());
    return out;
}

void family_errors::add(const pair_errors& e) {
    ++pairs;
    if (!e.measured) {
        ++skipped;
        return;
    }
    mismatched_normals += e.choice_matches_normal ? 0u : 1u;
    choice_differs += e.choice_differs ? 1u : 0u;
    incident_differs += e.incident_differs ? 1u : 0u;
    count_differs += e.count_differs ? 1u : 0u;
    count_differs_exact_choice += e.count_differs_exact_choice ? 1u : 0u;
    normal_u = std::max(normal_u, e.normal_angle / e.unit);
    if (e.size > 0) {
        depth_size = std::max(depth_size, e.depth_error / e.size);
        point_size = std::max(point_size, e.point_error / e.size);
        depth_exact_choice_size = std::max(depth_exact_choice_size, e.depth_error_exact_choice / e.size);
    }
    depth_u_reach = std::max(depth_u_reach, e.depth_error / (e.unit * e.reach));
    separation_u_reach = std::max(separation_u_reach, e.separation_error / (e.unit * e.reach));
    point_u_scale = std::max(point_u_scale, e.point_error / (e.unit * (e.offset + e.reach)));
    if (e.count_differs) {
        count_boundary_u_reach = std::max(count_boundary_u_reach, e.count_boundary);
    }
    normal_exact_choice = std::max(normal_exact_choice, e.normal_angle_exact_choice);
}

family_result measure_family(const std::vector<pose_pair>& pairs) {
    family_result out;
    for (const pose_pair& pair : pairs) {
        out.poses.add(measure_poses(pair.a, pair.b));
        out.corners.add(measure_corners(corners_of(pair.a), corners_of(pair.b)));
    }
    return out;
}


family_result measure_family(const std::vector<pose_pair64>& pairs) {
    const double_contacts contacts = contacts_through_the_api(pairs);
    family_result out;
    std::size_t quad = 0;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        out.poses.add(measure_poses(pairs[i].a, pairs[i].b, contacts.poses[i]));
        out.corners.add(contacts.corners_measured[i]
                            ? measure_corners(corners_of(pairs[i].a), corners_of(pairs[i].b), contacts.corners[quad++])
                            : pair_errors{});
    }
    return out;
}

}  // namespace obbsat::accuracy
