#include <obbsat/ref/local.hpp>

#include <cmath>

namespace obbsat::ref {

pose_axes local_axes(const rect_pose& a, const rect_pose& b) {
    const float ca = a.rotation.x, sa = a.rotation.y;
    const float cb = b.rotation.x, sb = b.rotation.y;
    const float hxa = a.half_extents.x, hya = a.half_extents.y;
    const float hxb = b.half_extents.x, hyb = b.half_extents.y;

    const float dx = b.center.x - a.center.x;
    const float dy = b.center.y - a.center.y;

    const float P = std::fabs((ca * cb) + (sa * sb));
    const float Q = std::fabs((ca * sb) - (sa * cb));
    const float na = (ca * ca) + (sa * sa);
    const float nb = (cb * cb) + (sb * sb);

    pose_axes out;
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

bool shows_overlap(const pose_axes& axes, int k) { return std::fabs(axes.offset[k]) <= axes.reach[k]; }

bool local(const rect_pose& a, const rect_pose& b) {
    const pose_axes axes = local_axes(a, b);
    for (int k = 0; k < 4; ++k) {
        if (!shows_overlap(axes, k)) {
            return false;
        }
    }
    return true;
}

}  // namespace obbsat::ref
