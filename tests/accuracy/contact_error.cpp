#include "contact_error.hpp"

#include <obbsat/ref/contact.hpp>
#include <obbsat/ref/local.hpp>

#include <algorithm>
#include <cmath>

namespace obbsat::accuracy {

namespace {

// The float reference's steps 1 to 3 (P1 to P3 on poses), as its header
// states them: which face it takes as the reference. The contact does not
// say so when it has no points; the measurement checks that the normal it
// gives is this face's, bit for bit, so the two cannot drift apart.
float dot(point p, point q) { return (p.x * q.x) + (p.y * q.y); }
float min_of(float u, float v) { return u < v ? u : v; }
float max_of(float u, float v) { return u > v ? u : v; }

struct float_choice {
    face_choice face;
    int incident;  // step 5's face of the incident box
    float nx, ny;  // the normal it gives
};

/// Step 5: the incident box's face most against u = (ux, uy), the first by strict <.
int incident_face(const ref::contact_box& inc, const float inc_inv[4], float ux, float uy) {
    int k = 0;
    float most_against = dot(inc.n[0], point{ux, uy}) * inc_inv[0];
    for (int f = 1; f < 4; ++f) {
        const float along = dot(inc.n[f], point{ux, uy}) * inc_inv[f];
        if (along < most_against) {
            most_against = along;
            k = f;
        }
    }
    return k;
}

float_choice float_choice_of(const rect_pose& a, const rect_pose& b) {
    const float len_a = std::sqrt(dot(a.rotation, a.rotation)), len_b = std::sqrt(dot(b.rotation, b.rotation));
    const float inv_a = 1.0f / len_a, inv_b = 1.0f / len_b;
    const ref::pose_axes axes = ref::local_axes(a, b);
    float sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (std::fabs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? inv_a : inv_b);
    }
    const bool a_on_y = sep[1] > sep[0], b_on_y = sep[3] > sep[2];
    const float sa = a_on_y ? sep[1] : sep[0], sb = b_on_y ? sep[3] : sep[2];
    const float size_a = (a.half_extents.x + a.half_extents.y) * len_a;
    const float size_b = (b.half_extents.x + b.half_extents.y) * len_b;
    const bool flip = sb > (sa + 0x1p-10f * min_of(size_a, size_b));
    int r = 0;
    if (!flip) {
        r = a_on_y ? (axes.offset[1] >= 0.0f ? 0 : 2) : (axes.offset[0] >= 0.0f ? 1 : 3);
    } else {
        r = b_on_y ? (axes.offset[3] >= 0.0f ? 2 : 0) : (axes.offset[2] >= 0.0f ? 3 : 1);
    }
    const ref::contact_box ref_box = ref::contact_box_of(flip ? b : a, a.center);
    const ref::contact_box inc_box = ref::contact_box_of(flip ? a : b, a.center);
    const float inv = flip ? inv_b : inv_a;
    const float inc_inv[4] = {flip ? inv_a : inv_b, flip ? inv_a : inv_b, flip ? inv_a : inv_b, flip ? inv_a : inv_b};
    const float ux = ref_box.n[r].x * inv, uy = ref_box.n[r].y * inv;
    return float_choice{face_choice{flip, r}, incident_face(inc_box, inc_inv, ux, uy), flip ? -ux : ux,
                        flip ? -uy : uy};
}

float span(const ref::contact_box& box) {
    float lo_x = box.v[0].x, hi_x = box.v[0].x, lo_y = box.v[0].y, hi_y = box.v[0].y;
    for (int j = 1; j < 4; ++j) {
        lo_x = min_of(box.v[j].x, lo_x);
        hi_x = max_of(box.v[j].x, hi_x);
        lo_y = min_of(box.v[j].y, lo_y);
        hi_y = max_of(box.v[j].y, hi_y);
    }
    return max_of(hi_x - lo_x, hi_y - lo_y);
}

int best_face(const ref::contact_box& faces, const float inv[4], const ref::contact_box& other, float& best_sep) {
    int best = 0;
    for (int k = 0; k < 4; ++k) {
        const point d0{other.v[0].x - faces.v[k].x, other.v[0].y - faces.v[k].y};
        float least = dot(faces.n[k], d0);
        for (int j = 1; j < 4; ++j) {
            const point d{other.v[j].x - faces.v[k].x, other.v[j].y - faces.v[k].y};
            least = min_of(dot(faces.n[k], d), least);
        }
        const float sep = least * inv[k];
        if (k == 0 || sep > best_sep) {
            best = k;
            best_sep = sep;
        }
    }
    return best;
}

float_choice float_choice_of(const rect& a, const rect& b) {
    const ref::contact_box box_a = ref::contact_box_of(a, a.ul), box_b = ref::contact_box_of(b, a.ul);
    float inv_a[4], inv_b[4];
    for (int k = 0; k < 4; ++k) {
        inv_a[k] = 1.0f / std::sqrt(dot(box_a.n[k], box_a.n[k]));
        inv_b[k] = 1.0f / std::sqrt(dot(box_b.n[k], box_b.n[k]));
    }
    float sa = 0, sb = 0;
    const int ia = best_face(box_a, inv_a, box_b, sa), ib = best_face(box_b, inv_b, box_a, sb);
    const bool flip = sb > (sa + 0x1p-10f * min_of(span(box_a), span(box_b)));
    const int r = flip ? ib : ia;
    const ref::contact_box& ref_box = flip ? box_b : box_a;
    const float inv = flip ? inv_b[r] : inv_a[r];
    const float ux = ref_box.n[r].x * inv, uy = ref_box.n[r].y * inv;
    const int k = flip ? incident_face(box_a, inv_a, ux, uy) : incident_face(box_b, inv_b, ux, uy);
    return float_choice{face_choice{flip, r}, k, flip ? -ux : ux, flip ? -uy : uy};
}

double to_double(const mpf_class& v) { return v.get_d(); }
mpf_class mpf_of(float v) { return mpf_class(static_cast<double>(v), contact_exact_bits); }
mpf_class mpf_of(const mpq_class& v) { return mpf_class(v, contact_exact_bits); }

/// The angle between the float normal and the exact one.
double angle_between(const contact& c, const exact_contact& e) {
    const mpf_class fx = mpf_of(c.nx), fy = mpf_of(c.ny);
    const mpf_class sine = fx * e.ny - fy * e.nx, cosine = fx * e.nx + fy * e.ny;
    return std::atan2(std::fabs(to_double(sine)), to_double(cosine));
}

double point_distance(const contact_point& p, const exact_point& q) {
    const mpf_class dx = mpf_of(p.x) - mpf_of(q.x), dy = mpf_of(p.y) - mpf_of(q.y);
    return std::hypot(to_double(dx), to_double(dy));
}

double largest_coordinate(const exact_box& box, point origin) {
    double reach = 0;
    for (const exact_point& v : box.v) {
        reach = std::max(reach, std::fabs(mpq_class(v.x - mpq_class(static_cast<double>(origin.x))).get_d()));
        reach = std::max(reach, std::fabs(mpq_class(v.y - mpq_class(static_cast<double>(origin.y))).get_d()));
    }
    return reach;
}

/// The part shared by poses and corners, once both boxes and choices are known.
pair_errors measure(const contact& c, const float_choice& chosen, const exact_box& a, const exact_box& b,
                    const exact_choice& exact, point origin, double size) {
    pair_errors out;
    out.measured = true;
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
        out.count_boundary = boundary / (unit_roundoff * out.reach);
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

}  // namespace

pair_errors measure_poses(const rect_pose& a, const rect_pose& b) {
    const contact c = ref::contact_of(a, b);
    const exact_box box_a = exact_box_of(a), box_b = exact_box_of(b);
    double size = 0;
    for (const rect_pose* p : {&a, &b}) {
        const double length = std::hypot(static_cast<double>(p->rotation.x), static_cast<double>(p->rotation.y));
        size = std::max({size, p->half_extents.x * length, p->half_extents.y * length});
    }
    return measure(c, float_choice_of(a, b), box_a, box_b, exact_choice_of(a, b), a.center, size);
}

pair_errors measure_corners(const rect& a, const rect& b) {
    exact_box box_a, box_b;
    if (!ref::corners_accepted(a) || !ref::corners_accepted(b) || !exact_box_of(a, box_a) ||
        !exact_box_of(b, box_b)) {
        return pair_errors{};
    }
    const contact c = ref::contact_of(a, b);
    double size = 0;
    for (const exact_box* box : {&box_a, &box_b}) {
        for (int k = 0; k < 4; ++k) {
            size = std::max(size, std::sqrt(box->n2[k].get_d()) / 2);
        }
    }
    return measure(c, float_choice_of(a, b), box_a, box_b, exact_choice_of(box_a, box_b), a.ul, size);
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
    normal_u = std::max(normal_u, e.normal_angle / unit_roundoff);
    if (e.size > 0) {
        depth_size = std::max(depth_size, e.depth_error / e.size);
        point_size = std::max(point_size, e.point_error / e.size);
        depth_exact_choice_size = std::max(depth_exact_choice_size, e.depth_error_exact_choice / e.size);
    }
    depth_u_reach = std::max(depth_u_reach, e.depth_error / (unit_roundoff * e.reach));
    separation_u_reach = std::max(separation_u_reach, e.separation_error / (unit_roundoff * e.reach));
    point_u_scale = std::max(point_u_scale, e.point_error / (unit_roundoff * (e.offset + e.reach)));
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

}  // namespace obbsat::accuracy
