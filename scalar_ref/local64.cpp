#include <obbsat/ref/local64.hpp>

#include <cmath>

namespace obbsat::ref {

pose_axes64 local_axes(const rect_pose64& a, const rect_pose64& b) {
    const double ca = a.rotation.x, sa = a.rotation.y;
    const double cb = b.rotation.x, sb = b.rotation.y;
    const double hxa = a.half_extents.x, hya = a.half_extents.y;
    const double hxb = b.half_extents.x, hyb = b.half_extents.y;

    const double dx = b.center.x - a.center.x;
    const double dy = b.center.y - a.center.y;

    const double P = std::fabs((ca * cb) + (sa * sb));
    const double Q = std::fabs((ca * sb) - (sa * cb));
    const double na = (ca * ca) + (sa * sa);
    const double nb = (cb * cb) + (sb * sb);

    pose_axes64 out;
    out.offset[0] = (dx * ca) + (dy * sa);
    out.reach[0] = ((hxa * na) + (hxb * P)) + (hyb * Q);
    out.offset[1] = (dy * ca) - (dx * sa);
    out.reach[1] = ((hya * na) + (hxb * Q)) + (hyb * P);
    out.offset[2] = (dx * cb) + (dy * sb);
    out.reach[2] = ((hxb * nb) + (hxa * P)) + (hya * Q);
    out.offset[3] = (dy * cb) - (dx * sb);
    out.reach[3] = ((hyb * nb) + (hxa * Q)) + (hya * P);
    out.dx = dx;
    out.dy = dy;
    return out;
}

bool shows_overlap(const pose_axes64& axes, int k) { return std::fabs(axes.offset[k]) <= axes.reach[k]; }

bool local(const rect_pose64& a, const rect_pose64& b) {
    const pose_axes64 axes = local_axes(a, b);
    for (int k = 0; k < 4; ++k) {
        if (!shows_overlap(axes, k)) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::ref
