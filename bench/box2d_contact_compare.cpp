// Not a benchmark: `obbsat_box2d_contact_compare` compares, untimed, obbsat's
// contact_pairs with Box2D 2.4's b2CollidePolygons on the pairs the contact
// rows time (contact_workload.hpp: the typical-density scene of 4K and 256K
// pairs, as poses), the boxes built as peer_box2d_contacts.cpp builds them.
// It prints the tables of docs/contacts.md's "Against Box2D".
//
// What Box2D does differently, and what each table isolates:
//   - skin: every polygon has b2_polygonRadius = 2·b2_linearSlop (0.01) around
//     it; a pair gets points while its faces are within the two skins (0.02)
//     apart, and the incident edge is clipped against the reference face's
//     side planes pushed out by 0.02. Box2D's manifold keeps the clipped
//     incident points (localPoint), which are compared here with obbsat's,
//     before Box2D's world manifold moves them halfway across the skins.
//   - reference face: Box2D takes B's face when it separates more than A's by
//     k_tol = 0.1·b2_linearSlop (0.0005, an absolute length); obbsat by
//     2^-10 of the smaller box's size. Near ties the two pick different faces.
//   - rounding: Box2D builds each box's world vertices from the angle's
//     cosine and sine; obbsat from the pose's rotation vector, exactly.
#include "contact_workload.hpp"

#include <obbsat/contact.hpp>
#include <obbsat/ref/local.hpp>

#include <box2d/b2_collision.h>
#include <box2d/b2_common.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

namespace obbsat_bench {

// The same cache contract as bench_contact.cpp's, for this program alone.
workload& contact_workload(std::size_t pairs) {
    static std::map<std::size_t, std::unique_ptr<workload>> cache;
    std::unique_ptr<workload>& w = cache[pairs];
    if (!w) {
        w = std::make_unique<workload>(pairs, obbsat::scene_density::typical);
    }
    return *w;
}

}  // namespace obbsat_bench

namespace {

/// A normal angle beyond this (radians) means the other reference face.
constexpr double other_face_angle = 1e-3;

struct distribution {
    std::vector<double> values;
    double quantile(double q) {
        if (values.empty()) {
            return 0;
        }
        const std::size_t at = std::min(values.size() - 1, static_cast<std::size_t>(q * static_cast<double>(values.size())));
        std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
        return values[at];
    }
    double max() const { return values.empty() ? 0 : *std::max_element(values.begin(), values.end()); }
};

/// Box2D's manifold read back in world coordinates (identity transforms):
/// the normal from A to B and, per point, the clipped incident point and its
/// separation from the reference face without the skins.
struct box2d_contact {
    int count = 0;
    double nx = 0, ny = 0;
    double x[2] = {}, y[2] = {}, separation[2] = {};
};

/// Whether obbsat's reference face is B's: pose steps P1 to P3 of
/// obbsat/ref/contact.hpp (the contact does not say so by itself).
bool obbsat_takes_b_face(const obbsat::rect_pose& a, const obbsat::rect_pose& b) {
    const float len_a = std::sqrt((a.rotation.x * a.rotation.x) + (a.rotation.y * a.rotation.y));
    const float len_b = std::sqrt((b.rotation.x * b.rotation.x) + (b.rotation.y * b.rotation.y));
    const obbsat::ref::pose_axes axes = obbsat::ref::local_axes(a, b);
    float sep[4];
    for (int k = 0; k < 4; ++k) {
        sep[k] = (std::fabs(axes.offset[k]) - axes.reach[k]) * (k < 2 ? 1.0f / len_a : 1.0f / len_b);
    }
    const float sa = sep[1] > sep[0] ? sep[1] : sep[0], sb = sep[3] > sep[2] ? sep[3] : sep[2];
    const float size_a = (a.half_extents.x + a.half_extents.y) * len_a;
    const float size_b = (b.half_extents.x + b.half_extents.y) * len_b;
    return sb > (sa + 0x1p-10f * std::min(size_a, size_b));
}

box2d_contact read_manifold(const b2Manifold& m) {
    box2d_contact out;
    out.count = m.pointCount;
    const double sign = m.type == b2Manifold::e_faceB ? -1.0 : 1.0;
    out.nx = sign * m.localNormal.x;
    out.ny = sign * m.localNormal.y;
    for (int k = 0; k < m.pointCount; ++k) {
        out.x[k] = m.points[k].localPoint.x;
        out.y[k] = m.points[k].localPoint.y;
        out.separation[k] = (out.x[k] - m.localPoint.x) * m.localNormal.x + (out.y[k] - m.localPoint.y) * m.localNormal.y;
    }
    return out;
}

void compare(std::size_t count) {
    obbsat_bench::workload& w = obbsat_bench::contact_workload(count);
    const obbsat::pose_records& poses = w.poses();
    const std::vector<obbsat::pair_index>& pairs = w.sorted_pairs();
    std::vector<obbsat::contact> ours(count);
    const obbsat::backend ran = obbsat::contact_pairs(poses, pairs.data(), count, ours.data());

    std::vector<b2PolygonShape> boxes(poses.size());
    distribution sizes;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const obbsat::rect_pose p = poses[i];
        const float length = std::sqrt((p.rotation.x * p.rotation.x) + (p.rotation.y * p.rotation.y));
        boxes[i].SetAsBox(p.half_extents.x * length, p.half_extents.y * length, b2Vec2(p.center.x, p.center.y),
                          std::atan2(p.rotation.y, p.rotation.x));
        sizes.values.push_back(std::max(p.half_extents.x, p.half_extents.y) * static_cast<double>(length));
    }
    b2Transform identity;
    identity.SetIdentity();

    const double skins = 2.0 * b2_polygonRadius;
    std::size_t ours_only = 0, theirs_only = 0, theirs_only_in_skin = 0, both = 0, neither = 0;
    std::size_t same_count = 0, more_in_box2d = 0, more_in_obbsat = 0, other_face = 0;
    std::size_t extra_in_skin = 0, extra_beyond_side = 0;
    std::size_t other_box = 0;
    double farthest = 0;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        farthest = std::max({farthest, std::fabs(static_cast<double>(poses[i].center.x)),
                             std::fabs(static_cast<double>(poses[i].center.y))});
    }
    distribution normal_angle, same_face_angle, kept_distance, clipped_distance, kept_separation, clipped_separation;
    for (std::size_t i = 0; i < count; ++i) {
        b2Manifold manifold;
        b2CollidePolygons(&manifold, &boxes[pairs[i].a], identity, &boxes[pairs[i].b], identity);
        const box2d_contact theirs = read_manifold(manifold);
        const obbsat::contact& c = ours[i];
        const int n = static_cast<int>(c.point_count);
        if (n == 0 && theirs.count == 0) {
            ++neither;
            continue;
        }
        if (n == 0) {
            ++theirs_only;
            theirs_only_in_skin += (c.depth < 0 && -c.depth <= skins) ? 1u : 0u;
            continue;
        }
        if (theirs.count == 0) {
            ++ours_only;
            continue;
        }
        ++both;
        const double angle = std::atan2(std::fabs(c.nx * theirs.ny - c.ny * theirs.nx), c.nx * theirs.nx + c.ny * theirs.ny);
        normal_angle.values.push_back(angle);
        if (obbsat_takes_b_face(poses[pairs[i].a], poses[pairs[i].b]) != (manifold.type == b2Manifold::e_faceB)) {
            ++other_box;
            continue;
        }
        if (angle > other_face_angle) {
            ++other_face;
            continue;
        }
        same_face_angle.values.push_back(angle);
        if (n != theirs.count) {
            // Box2D's extra point: within the skins of the face, or clipped
            // against a side plane pushed out by the skins.
            if (theirs.count > n) {
                ++more_in_box2d;
                bool in_skin = false;
                for (int k = 0; k < theirs.count; ++k) {
                    in_skin = in_skin || theirs.separation[k] > 0;
                }
                extra_in_skin += in_skin ? 1u : 0u;
                extra_beyond_side += in_skin ? 0u : 1u;
            } else {
                ++more_in_obbsat;
            }
            continue;
        }
        ++same_count;
        for (int k = 0; k < n; ++k) {
            double nearest = INFINITY, its_separation = 0;
            for (int j = 0; j < theirs.count; ++j) {
                const double d = std::hypot(c.points[k].x - theirs.x[j], c.points[k].y - theirs.y[j]);
                if (d < nearest) {
                    nearest = d;
                    its_separation = theirs.separation[j];
                }
            }
            // An end of the incident edge left in place has a vertex of the
            // incident box in its key; one moved to a side plane has a face.
            const obbsat::contact_feature f = c.points[k].feature;
            const bool left_in_place = (f.type_a == obbsat::feature_type::vertex) ==
                                       (manifold.type == b2Manifold::e_faceB);
            (left_in_place ? kept_distance : clipped_distance).values.push_back(nearest);
            (left_in_place ? kept_separation : clipped_separation)
                .values.push_back(std::fabs(c.points[k].separation - its_separation));
        }
    }

    std::printf("### %zu pairs (obbsat backend %s; median larger half extent %.3g; centers up to %.3g from the "
                "origin)\n\n",
                count, obbsat::backend_name(ran), sizes.quantile(0.5), farthest);
    std::printf("| points from | pairs |\n| --- | --- |\n");
    std::printf("| both | %zu |\n| neither | %zu |\n| Box2D only | %zu (apart by at most the skins 0.02: %zu) |\n"
                "| obbsat only | %zu |\n\n",
                both, neither, theirs_only, theirs_only_in_skin, ours_only);
    std::printf("| of the %zu pairs with points from both | pairs |\n| --- | --- |\n", both);
    std::printf("| reference face on the other box (A's against B's) | %zu |\n", other_box);
    std::printf("| another face of the same box (normals > %.0e rad apart) | %zu |\n", other_face_angle, other_face);
    std::printf("| same face, same point count | %zu |\n", same_count);
    std::printf("| same face, Box2D has more points | %zu (a point within the skins: %zu; clipped beyond a side: %zu) |\n",
                more_in_box2d, extra_in_skin, extra_beyond_side);
    std::printf("| same face, obbsat has more points | %zu |\n\n", more_in_obbsat);
    std::printf("| difference | p50 | p99 | max |\n| --- | --- | --- | --- |\n");
    const double angle_p50 = normal_angle.quantile(0.5), angle_p99 = normal_angle.quantile(0.99);
    std::printf("| normal angle, all pairs with points from both (rad) | %.2e | %.2e | %.2e |\n", angle_p50, angle_p99,
                normal_angle.max());
    const double same_p50 = same_face_angle.quantile(0.5), same_p99 = same_face_angle.quantile(0.99);
    std::printf("| normal angle, same reference face (rad) | %.2e | %.2e | %.2e |\n", same_p50, same_p99,
                same_face_angle.max());
    const double k50 = kept_distance.quantile(0.5), k99 = kept_distance.quantile(0.99);
    std::printf("| point distance, same face and count, incident corner left in place | %.2e | %.2e | %.2e |\n", k50,
                k99, kept_distance.max());
    const double c50 = clipped_distance.quantile(0.5), c99 = clipped_distance.quantile(0.99);
    std::printf("| point distance, same face and count, clipped to a side plane | %.2e | %.2e | %.2e |\n", c50, c99,
                clipped_distance.max());
    const double s50 = kept_separation.quantile(0.5), s99 = kept_separation.quantile(0.99);
    std::printf("| separation (Box2D's without skins), same face and count, left in place | %.2e | %.2e | %.2e |\n",
                s50, s99, kept_separation.max());
    const double t50 = clipped_separation.quantile(0.5), t99 = clipped_separation.quantile(0.99);
    std::printf("| separation (Box2D's without skins), same face and count, clipped | %.2e | %.2e | %.2e |\n\n", t50,
                t99, clipped_separation.max());
}

}  // namespace

int main() {
    for (const std::size_t count : obbsat_bench::contact_sizes) {
        compare(count);
    }
    return 0;
}
