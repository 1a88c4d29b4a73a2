#include "geometry.hpp"

#include <cmath>

namespace obbsat::suites::detail {

vec unit_from_parameter(double t) {
    const double denominator = 1.0 + t * t;
    return vec{(1.0 - t * t) / denominator, (2.0 * t) / denominator};
}

vec normalized(vec v) {
    const double length = std::sqrt(dot(v, v));
    return vec{v.x / length, v.y / length};
}

quad box(vec center, vec axis, double half_width, double half_height) {
    return quad{center + rotate(vec{-half_width, half_height}, axis),
                center + rotate(vec{half_width, half_height}, axis),
                center + rotate(vec{half_width, -half_height}, axis),
                center + rotate(vec{-half_width, -half_height}, axis)};
}

quad translated(const quad& q, vec offset) {
    return quad{q[0] + offset, q[1] + offset, q[2] + offset, q[3] + offset};
}

quad scaled(const quad& q, double scale, vec offset) {
    return quad{scale * q[0] + offset, scale * q[1] + offset, scale * q[2] + offset,
                scale * q[3] + offset};
}

rect to_rect(const quad& q) {
    auto corner = [](vec v) { return point{static_cast<float>(v.x), static_cast<float>(v.y)}; };
    return rect{corner(q[0]), corner(q[1]), corner(q[2]), corner(q[3])};
}

quad to_quad(const rect& r) {
    auto corner = [](point p) { return vec{static_cast<double>(p.x), static_cast<double>(p.y)}; };
    return quad{corner(r.ul), corner(r.ur), corner(r.lr), corner(r.ll)};
}

vec centroid(const quad& q) {
    return 0.25 * (q[0] + q[1] + q[2] + q[3]);
}

}  // namespace obbsat::suites::detail
