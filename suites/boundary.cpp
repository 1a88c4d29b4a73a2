#include <obbsat/suites/boundary.hpp>

#include <obbsat/oracle/contact.hpp>
#include <obbsat/oracle/pose_contact.hpp>

#include <cmath>

namespace obbsat::suites {

namespace {

float step_floats(float v, int steps) {
    const float towards = steps > 0 ? INFINITY : -INFINITY;
    for (int i = 0; i < (steps > 0 ? steps : -steps); ++i) {
        v = std::nextafter(v, towards);
    }
    return v;
}

point nudge_point(point p, int steps_x, int steps_y) {
    return point{step_floats(p.x, steps_x), step_floats(p.y, steps_y)};
}

bool is_finite(const rect& r) {
    return std::isfinite(r.ul.x) && std::isfinite(r.ul.y) && std::isfinite(r.ur.x) &&
           std::isfinite(r.ur.y) && std::isfinite(r.lr.x) && std::isfinite(r.lr.y) &&
           std::isfinite(r.ll.x) && std::isfinite(r.ll.y);
}

bool is_finite(const rect_pose& p) {
    return std::isfinite(p.center.x) && std::isfinite(p.center.y);
}

}  // namespace

rect nudge(const rect& r, int steps_x, int steps_y) {
    return rect{nudge_point(r.ul, steps_x, steps_y), nudge_point(r.ur, steps_x, steps_y),
                nudge_point(r.lr, steps_x, steps_y), nudge_point(r.ll, steps_x, steps_y)};
}

rect_pose nudge(const rect_pose& p, int steps_x, int steps_y) {
    return rect_pose{nudge_point(p.center, steps_x, steps_y), p.half_extents, p.rotation};
}

namespace {

// Shape is rect or rect_pose: b moved by 1..steps floats in each direction.
template <class Shape>
bool near_boundary(const Shape& a, const Shape& b, unsigned steps) {
    using oracle::contact;
    const contact here = oracle::classify(a, b);
    if (here == contact::touching) {
        return true;
    }
    const int directions[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : directions) {
        for (unsigned s = 1; s <= steps; ++s) {
            const int k = static_cast<int>(s);
            const Shape moved = nudge(b, d[0] * k, d[1] * k);
            if (is_finite(moved) && oracle::classify(a, moved) != here) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace

bool near_contact_boundary(const rect& a, const rect& b, unsigned steps) {
    return near_boundary(a, b, steps);
}

bool near_contact_boundary(const rect_pose& a, const rect_pose& b, unsigned steps) {
    return near_boundary(a, b, steps);
}

}  // namespace obbsat::suites
