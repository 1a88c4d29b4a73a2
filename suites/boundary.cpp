#include <obbsat/suites/boundary.hpp>

#include <obbsat/oracle/contact.hpp>

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

point nudge(point p, int steps_x, int steps_y) {
    return point{step_floats(p.x, steps_x), step_floats(p.y, steps_y)};
}

bool is_finite(const rect& r) {
    return std::isfinite(r.ul.x) && std::isfinite(r.ul.y) && std::isfinite(r.ur.x) &&
           std::isfinite(r.ur.y) && std::isfinite(r.lr.x) && std::isfinite(r.lr.y) &&
           std::isfinite(r.ll.x) && std::isfinite(r.ll.y);
}

}  // namespace

rect nudge(const rect& r, int steps_x, int steps_y) {
    return rect{nudge(r.ul, steps_x, steps_y), nudge(r.ur, steps_x, steps_y),
                nudge(r.lr, steps_x, steps_y), nudge(r.ll, steps_x, steps_y)};
}

bool near_contact_boundary(const rect& a, const rect& b, unsigned steps) {
    using oracle::contact;
    const contact here = oracle::classify(a, b);
    if (here == contact::touching) {
        return true;
    }
    const int directions[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& d : directions) {
        for (unsigned s = 1; s <= steps; ++s) {
            const int k = static_cast<int>(s);
            const rect moved = nudge(b, d[0] * k, d[1] * k);
            if (is_finite(moved) && oracle::classify(a, moved) != here) {
                return true;
            }
        }
    }
    return false;
}

}  // namespace obbsat::suites
